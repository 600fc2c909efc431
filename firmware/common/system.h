/* system.h - tick timer, watchdog and idle sleep shared by every image.
 *
 * Timer0 overflows every 9.984 ms (prescaler 64, reload 0x64 as in the
 * thesis listings); that is the "tick" every delay of the protocol counts
 * in. The main loop never spins: sys_idle() sleeps in idle mode until the
 * next interrupt (the tick or a UART), which bounds every wait by one tick.
 *
 * A loop that knows the next tick at which it has anything to do sleeps
 * with sys_idle_until() instead: the tick interrupts before that tick only
 * count time, and the loop's pass does not run for them (docs/firmware.md,
 * "The idle path"). Its pattern:
 *
 *     for (;;) {
 *         uint8_t mark = sys_io_events;   // before looking at any input
 *         ...look at the inputs and the time, act...
 *         sys_idle_until(next_due, mark); // next_due: earliest tick that matters
 *     }
 */
#ifndef SYSTEM_H
#define SYSTEM_H

#include <stdint.h>

typedef uint16_t tick_t;

/** Start the tick, arm the watchdog (2 s) and enable interrupts. */
void sys_init(void);

/** MCUCSR as it was at reset (PORF, EXTRF, BORF, WDRF: why we started). */
uint8_t sys_reset_flags(void);

/** Ticks since boot (wraps after 655 s; compare with tick_since()). */
tick_t tick_now(void);

/** Ticks elapsed since @p start, wrap-safe for spans under 655 s. */
static inline tick_t tick_since(tick_t start)
{
    return (tick_t)(tick_now() - start);
}

/** Sleep (idle mode) until the next interrupt; feeds the watchdog. */
void sys_idle(void);

/** Interrupts other than the tick so far (a UART byte received, a transmit
 *  slot freed), wrapping: read it before a loop looks at its inputs. */
extern volatile uint8_t sys_io_events;

/** Longest sys_idle_until() sleeps in one call: far below the watchdog's
 *  2 s, so the watchdog still bites a main loop that stops coming back. */
#define SYS_IDLE_MAX_TICKS 100u

/** Sleep (idle mode) until an interrupt other than the tick has run since
 *  @p mark was read from sys_io_events, or until tick_now() reaches @p due,
 *  or SYS_IDLE_MAX_TICKS have passed; returns at once if one of these holds
 *  already. Feeds the watchdog once. */
void sys_idle_until(tick_t due, uint8_t mark);

/** The earlier of two ticks (both within 327 s of each other). */
static inline tick_t tick_earlier(tick_t a, tick_t b)
{
    return (int16_t)(a - b) < 0 ? a : b;
}

/** Sleep for @p ticks ticks (10 ms each), feeding the watchdog. */
void sys_delay(tick_t ticks);

/** A poll's own deadlines: the earlier of @p due and the next tick at which
 *  the poll has something to do with no new input (a time-out). */
typedef tick_t (*due_fn)(tick_t due);

/** Like sys_delay(), calling @p poll at every wake-up that matters (an
 *  input, or a tick that @p due names); returns 1 as soon as it returns
 *  non-zero (a new command arrived), 0 after @p ticks. */
uint8_t sys_delay_polling(tick_t ticks, uint8_t (*poll)(void), due_fn due);

#endif /* SYSTEM_H */
