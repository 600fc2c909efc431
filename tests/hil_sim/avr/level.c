/* level.c -- INT0 in its reset-default low-level mode: while PD2 is held low
 * the interrupt repeats after every return; the handler counts on PORTA and
 * disables INT0 at 5.  The CPU sleeps in between. */
#include <avr/interrupt.h>
#include <avr/io.h>
#include <avr/sleep.h>

ISR(INT0_vect)
{
	PORTA++;
	if (PORTA == 5)
		GICR &= (uint8_t)~(1 << INT0);
}

int main(void)
{
	DDRA = 0xFF;
	PORTD = (1 << PD2); /* pull-up: high until something pulls it low */
	GICR = (1 << INT0); /* ISC01:0 = 00: low level */
	set_sleep_mode(SLEEP_MODE_IDLE);
	sei();
	for (;;)
		sleep_mode();
}
