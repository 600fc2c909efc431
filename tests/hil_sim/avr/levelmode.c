/* levelmode.c -- INT0 switched from falling-edge to low-level mode while PD2
 * is already low: on the part the interrupt then repeats with nothing else
 * happening (no edge, no GICR write).  The handler counts on PORTA and
 * disables INT0 at 5 (test_core_edges.py). */
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
	PORTD = (1 << PD2);  /* pull-up: high until the test pulls it low */
	MCUCR = (1 << ISC01); /* falling edge */
	GICR = (1 << INT0);
	sei();
	while (PORTA == 0)
		;                 /* the edge's one interrupt */
	MCUCR = 0;            /* low level, with the pin still low */
	set_sleep_mode(SLEEP_MODE_IDLE);
	for (;;)
		sleep_mode();
}
