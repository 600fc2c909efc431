/* tick.c -- the firmware's 10 ms tick on Timer0 and the same on Timer2.
 *
 * Both timers run at clk/64 in normal mode and reload TCNT with 0x64 in the
 * overflow handler, as firmware/common/system.c does: 156 counts of 64
 * cycles = 9,984 cycles per tick.  Each handler bumps a counter on its own
 * port (A for Timer0, B for Timer2); the CPU sleeps in between, so every
 * handler starts the same number of cycles after its overflow. */
#include <avr/interrupt.h>
#include <avr/io.h>
#include <avr/sleep.h>

#define RELOAD 0x64

ISR(TIMER0_OVF_vect)
{
	TCNT0 = RELOAD;
	PORTA++;
}

ISR(TIMER2_OVF_vect)
{
	TCNT2 = RELOAD;
	PORTB++;
}

int main(void)
{
	DDRA = 0xFF;
	DDRB = 0xFF;
	TCNT0 = RELOAD;
	TCCR0 = (1 << CS01) | (1 << CS00); /* clk/64 */
	TCNT2 = RELOAD;
	TCCR2 = (1 << CS22);               /* clk/64 on Timer2's prescaler */
	TIMSK = (1 << TOIE0) | (1 << TOIE2);
	sei();
	sleep_enable();
	for (;;)
		sleep_cpu();
}
