/* system.c - Timer0 tick, watchdog and idle sleep. */
#include "system.h"

#include <avr/interrupt.h>
#include <avr/io.h>
#include <avr/sleep.h>
#include <avr/wdt.h>
#include <util/atomic.h>

#include "hexbot_codes.h"

/* The tick: 256 - HB_TICK_RELOAD counts of 64 us at the protocol's clock. */
#define TICK_RELOAD HB_TICK_RELOAD
_Static_assert(F_CPU == HB_F_CPU, "the Makefile's F_CPU is not the protocol's");

static volatile tick_t ticks;

ISR(TIMER0_OVF_vect)
{
    TCNT0 = TICK_RELOAD;
    ticks++;
}

void sys_init(void)
{
    /* Board init ran first (microseconds): only now may the watchdog start. */
    MCUCSR = 0;
    wdt_disable();
    TCCR0 = 0;
    TCNT0 = TICK_RELOAD;
    TCCR0 = (1 << CS01) | (1 << CS00); /* clk/64, normal mode */
    TIMSK |= (1 << TOIE0);
    set_sleep_mode(SLEEP_MODE_IDLE);
    wdt_enable(WDTO_2S);
    sei();
}

tick_t tick_now(void)
{
    tick_t t;
    ATOMIC_BLOCK(ATOMIC_RESTORESTATE) { t = ticks; }
    return t;
}

void sys_idle(void)
{
    wdt_reset();
    /* An interrupt between the caller's check and sleep_cpu() only costs
     * one tick of latency: the tick interrupt always wakes us. */
    sleep_enable();
    sei();
    sleep_cpu();
    sleep_disable();
}

void sys_delay(tick_t n)
{
    tick_t start = tick_now();
    while (tick_since(start) < n)
        sys_idle();
}

uint8_t sys_delay_polling(tick_t n, uint8_t (*poll)(void))
{
    tick_t start = tick_now();
    while (tick_since(start) < n) {
        if (poll())
            return 1;
        sys_idle();
    }
    return poll();
}
