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
volatile uint8_t sys_io_events;

/* The tick runs 100 times a second on every board, mostly to wake a CPU that
 * goes straight back to sleep: written by hand so that it saves one register
 * and SREG instead of gcc's five (r0, r1, SREG, r24, r25), and carries into
 * the high byte of ticks only when the low byte wraps (24 cycles against 40,
 * 16 instructions against 24). It reloads TCNT0 13 cycles after the
 * overflow, long before the next prescaler edge (64 cycles), so the tick
 * stays 156 x 64 cycles. Top-level asm, not an ISR_NAKED function, because
 * gcc cannot compute the stack use of a naked function (-fstack-usage). */
_Static_assert(TIMER0_OVF_vect_num == 17, "Timer0 overflow is not vector 17");
_Static_assert(_SFR_IO_ADDR(TCNT0) == 0x32, "TCNT0 is not at I/O 0x32");
_Static_assert(TICK_RELOAD == 0x64u, "the reload below is not HB_TICK_RELOAD");
__asm__(".pushsection .text.__vector_17,\"ax\",@progbits\n"
        ".global __vector_17\n"
        ".type __vector_17, @function\n"
        "__vector_17:\n"
        "\tpush r24\n"
        "\tin r24, 0x3f\n" /* SREG */
        "\tpush r24\n"
        "\tldi r24, 0x64\n" /* TICK_RELOAD */
        "\tout 0x32, r24\n" /* TCNT0 */
        "\tlds r24, ticks\n"
        "\tsubi r24, 0xFF\n" /* +1; Z set when the low byte wrapped */
        "\tsts ticks, r24\n"
        "\tbrne 1f\n"
        "\tlds r24, ticks+1\n"
        "\tsubi r24, 0xFF\n"
        "\tsts ticks+1, r24\n"
        "1:\tpop r24\n"
        "\tout 0x3f, r24\n"
        "\tpop r24\n"
        "\treti\n"
        ".size __vector_17, .-__vector_17\n"
        ".popsection\n");

static uint8_t reset_flags;

void sys_init(void)
{
    /* Board init ran first (microseconds): only now may the watchdog start.
     * The reset flags are kept for sys_reset_flags() before they are cleared
     * (a set WDRF would keep the next reset's cause ambiguous). */
    reset_flags = MCUCSR;
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

uint8_t sys_reset_flags(void)
{
    return reset_flags;
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

void sys_idle_until(tick_t due, uint8_t mark)
{
    wdt_reset();
    sleep_enable();
    cli();
    uint8_t start = (uint8_t)ticks;
    /* Checked with interrupts off; SEI lets SLEEP run before any interrupt,
     * so none can slip in between the check and the sleep, and an interrupt
     * already pending wakes it at once: its handler runs before the CLI
     * (avr-libc's documented idiom; the simulator's core follows the
     * datasheet here, docs/simulator-core.md item 17). */
    for (;;) {
        tick_t now = ticks;
        if (sys_io_events != mark || (int16_t)(now - due) >= 0 ||
            (uint8_t)((uint8_t)now - start) >= SYS_IDLE_MAX_TICKS)
            break;
        __asm__ __volatile__("sei\n\tsleep\n\tcli" ::: "memory");
    }
    sei();
    sleep_disable();
}

void sys_delay(tick_t n)
{
    tick_t start = tick_now();
    while (tick_since(start) < n)
        sys_idle_until(start + n, sys_io_events);
}

uint8_t sys_delay_polling(tick_t n, uint8_t (*poll)(void), due_fn due)
{
    /* A pattern of zero-tick waits (LCircle(255, 0): 9,180 of them) never
     * sleeps, so it is fed here; every such pattern is bounded. */
    wdt_reset();
    tick_t start = tick_now();
    while (tick_since(start) < n) {
        uint8_t mark = sys_io_events;
        if (poll())
            return 1;
        sys_idle_until(due((tick_t)(start + n)), mark);
    }
    return poll();
}
