/* latency.c -- interrupt latency after SEI, after RETI and around SLEEP.
 *
 * ATmega162 datasheet, "Reset and Interrupt Handling": the instruction
 * following SEI runs before any pending interrupt; after RETI one more
 * instruction of the main program runs before a pending interrupt; "sei;
 * sleep" enters sleep before any pending interrupt, and ("Interrupt Response
 * Time", "Sleep Modes") an interrupt that wakes the MCU costs four more
 * cycles: it is halted four cycles, runs the handler and resumes after SLEEP.
 *
 * The interrupts are made pending with I clear (a timer overflows, TOIE set),
 * then the main program runs "inc r18" after SEI; each handler stores r18, so
 * it tells how many main-program instructions ran first (distinct values:
 * the pin log records changes only).  Results go to
 * PORTA in this order:
 *   1. r18 at Timer0's handler after "sei; inc; inc; ..."        (part: 1)
 *   2. r18 at Timer2's handler, Timer0's also pending, r18 from 0x10
 *                                                                  (part: 0x11)
 *   3. r18 at Timer0's handler after Timer2's RETI                 (part: 0x12)
 *   4. 0x55 if Timer0's handler ran within "sei; sleep; cli"       (part: 0x55)
 *   5, 6. as 2, 3 from 0x60, but Timer2's handler ends "sei; reti": RETI with
 *      I already set still runs one main instruction first   (part: 0x61, 0x62)
 * PORTB carries timestamps: 0x10 written just before SEI, then Timer0's
 * handler writes r19 = 0x11 after "sei; nop" and 0x21 (after 0x20) after
 * "sei; sleep": the second gap is four cycles longer (the wake-up halt).
 * Each gap is exact on the part ("Interrupt Response Time": four cycles to
 * push the PC, the vector's JMP three): out, sei, nop, 4, jmp 3, sts 2 ->
 * 12 cycles to Timer0's "out"; with sleep for the nop, 4 more -> 16.
 * Then a timer overflows while the CPU spins (0x30 -> 0x31) and while it
 * sleeps (0x40 -> 0x41): four cycles longer again.  PORTA = 0xFF: done. */
#include <avr/interrupt.h>
#include <avr/io.h>
#include <avr/sleep.h>

volatile uint8_t seen0, seen2;

/* Handlers that touch neither SREG nor a register: r18..r20 belong to the
 * main program's asm blocks, the only places interrupts are enabled.
 * Timer2's handler re-enables interrupts just before its RETI if r20 bit 0
 * is set (SBRC leaves SREG alone). */
ISR(TIMER0_OVF_vect, ISR_NAKED)
{
	__asm__ __volatile__("sts seen0, r18\n\tout %0, r19\n\treti"
			     :: "I"(_SFR_IO_ADDR(PORTB)));
}

ISR(TIMER2_OVF_vect, ISR_NAKED)
{
	__asm__ __volatile__("sts seen2, r18\n\tsbrc r20, 0\n\tsei\n\treti");
}

/* Overflow Timer0 (and Timer2 if asked) with interrupts off: the overflow
 * interrupts are then pending when SEI runs.  The timers stop after. */
static void make_pending(uint8_t both)
{
	TCCR0 = 0;
	TCCR2 = 0;
	TIFR = (1 << TOV0) | (1 << TOV2);
	TIMSK = (1 << TOIE0) | (both ? (1 << TOIE2) : 0);
	TCNT0 = 0xF0;
	TCNT2 = 0xF0;
	TCCR0 = (1 << CS00);
	if (both)
		TCCR2 = (1 << CS20);
	while (!(TIFR & (1 << TOV0)) || (both && !(TIFR & (1 << TOV2))))
		;
	TCCR0 = 0;
	TCCR2 = 0;
}

/* Timer0 at clk/1 from 0xC0: overflows 64 cycles on, interrupts on. */
static void start_timer0(void)
{
	TIFR = (1 << TOV0);
	TIMSK = (1 << TOIE0);
	TCNT0 = 0xC0;
	TCCR0 = (1 << CS00);
}

int main(void)
{
	DDRA = 0xFF;
	DDRB = 0xFF;
	set_sleep_mode(SLEEP_MODE_IDLE);
	sleep_enable();

	/* 1: one instruction after SEI */
	make_pending(0);
	__asm__ __volatile__("ldi r18, 0\n\tldi r19, 0\n\tsei\n\t"
			     "inc r18\n\tinc r18\n\tinc r18\n\tinc r18\n\tcli"
			     ::: "r18", "r19", "memory");
	PORTA = seen0;

	/* 2, 3: Timer2 first (lower vector), one main instruction, Timer0 */
	make_pending(1);
	__asm__ __volatile__("ldi r18, 0x10\n\tldi r19, 0\n\tldi r20, 0\n\tsei\n\t"
			     "inc r18\n\tinc r18\n\tinc r18\n\tinc r18\n\t"
			     "inc r18\n\tinc r18\n\tcli"
			     ::: "r18", "r19", "r20", "memory");
	PORTA = seen2;
	PORTA = seen0;

	/* 4: "sei; sleep; cli" with the interrupt pending: it runs */
	seen0 = 0;
	make_pending(0);
	__asm__ __volatile__("ldi r18, 0x55\n\tldi r19, 0\n\tsei\n\tsleep\n\tcli"
			     ::: "r18", "r19", "memory");
	PORTA = seen0;

	/* 5, 6: the same, Timer2's handler ending "sei; reti" (I set at RETI) */
	make_pending(1);
	__asm__ __volatile__("ldi r18, 0x60\n\tldi r19, 0\n\tldi r20, 1\n\tsei\n\t"
			     "inc r18\n\tinc r18\n\tinc r18\n\tinc r18\n\t"
			     "inc r18\n\tinc r18\n\tcli"
			     ::: "r18", "r19", "r20", "memory");
	PORTA = seen2;
	PORTA = seen0;

	/* the wake-up halt, pending at SEI: "sei; nop" against "sei; sleep" */
	make_pending(0);
	__asm__ __volatile__("ldi r18, 0x10\n\tldi r19, 0x11\n\tout %0, r18\n\t"
			     "sei\n\tnop\n\tcli"
			     :: "I"(_SFR_IO_ADDR(PORTB)) : "r18", "r19", "memory");
	make_pending(0);
	__asm__ __volatile__("ldi r18, 0x20\n\tldi r19, 0x21\n\tout %0, r18\n\t"
			     "sei\n\tsleep\n\tcli"
			     :: "I"(_SFR_IO_ADDR(PORTB)) : "r18", "r19", "memory");

	/* the wake-up halt, an overflow while running against while asleep
	 * (same code from the timer's start to the timestamp in both) */
	start_timer0();
	__asm__ __volatile__("ldi r18, 0x30\n\tldi r19, 0x31\n\tout %0, r18\n\tsei\n\t"
			     ".rept 100\n\tnop\n\t.endr\n\tcli"
			     :: "I"(_SFR_IO_ADDR(PORTB)) : "r18", "r19", "memory");
	start_timer0();
	__asm__ __volatile__("ldi r18, 0x40\n\tldi r19, 0x41\n\tout %0, r18\n\tsei\n\t"
			     "sleep\n\tcli"
			     :: "I"(_SFR_IO_ADDR(PORTB)) : "r18", "r19", "memory");

	PORTA = 0xFF;
	for (;;)
		;
}
