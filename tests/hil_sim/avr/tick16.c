/* tick16.c -- the 10 ms tick of tick.c on the 16-bit Timer1 and Timer3.
 *
 * Both timers are set while stopped, then started at clk/64 in normal mode;
 * each overflow handler reloads TCNT = 0x10000 - 156 and bumps a counter on
 * its own port (A for Timer1, B for Timer3): 156 counts of 64 cycles = 9,984
 * cycles per tick. Timer3 starts half a tick in (78 counts) so that the two
 * handlers never wait for each other. */
#include <avr/interrupt.h>
#include <avr/io.h>
#include <avr/sleep.h>

#define RELOAD (0x10000UL - 156)
#define HALF (0x10000UL - 78)

ISR(TIMER1_OVF_vect)
{
	TCNT1 = RELOAD;
	PORTA++;
}

ISR(TIMER3_OVF_vect)
{
	TCNT3 = RELOAD;
	PORTB++;
}

int main(void)
{
	DDRA = 0xFF;
	DDRB = 0xFF;
	TCNT1 = RELOAD;                       /* written while the timer is stopped */
	TCNT3 = HALF;
	TCCR1B = (1 << CS11) | (1 << CS10);   /* clk/64 */
	TCCR3B = (1 << CS31) | (1 << CS30);   /* clk/64 (Timer3's own select) */
	TIMSK = (1 << TOIE1);
	ETIMSK = (1 << TOIE3);
	sei();
	sleep_enable();
	for (;;)
		sleep_cpu();
}
