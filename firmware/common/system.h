/* system.h - tick timer, watchdog and idle sleep shared by every image.
 *
 * Timer0 overflows every 9.984 ms (prescaler 64, reload 0x64 as in the
 * thesis listings); that is the "tick" every delay of the protocol counts
 * in. The main loop never spins: sys_idle() sleeps in idle mode until the
 * next interrupt (the tick or a UART), which bounds every wait by one tick.
 */
#ifndef SYSTEM_H
#define SYSTEM_H

#include <stdint.h>

typedef uint16_t tick_t;

/** Start the tick, arm the watchdog (2 s) and enable interrupts. */
void sys_init(void);

/** Ticks since boot (wraps after 655 s; compare with tick_since()). */
tick_t tick_now(void);

/** Ticks elapsed since @p start, wrap-safe for spans under 655 s. */
static inline tick_t tick_since(tick_t start)
{
    return (tick_t)(tick_now() - start);
}

/** Sleep (idle mode) until the next interrupt; feeds the watchdog. */
void sys_idle(void);

/** Sleep for @p ticks ticks (10 ms each), feeding the watchdog. */
void sys_delay(tick_t ticks);

/** Like sys_delay(), calling @p poll at every wake-up; returns 1 as soon as
 *  it returns non-zero (a new command arrived), 0 after @p ticks. */
uint8_t sys_delay_polling(tick_t ticks, uint8_t (*poll)(void));

#endif /* SYSTEM_H */
