/* dip.c -- inputs: PORTC pull-ups on, PINC copied to PORTB continuously
 * (the module-id DIP switches); INT0 (PD2, pull-up, falling edge) counts on
 * PORTA. */
#include <avr/interrupt.h>
#include <avr/io.h>

ISR(INT0_vect)
{
	PORTA++;
}

int main(void)
{
	DDRA = 0xFF;
	DDRB = 0xFF;
	PORTC = 0xFF;
	PORTD = (1 << PD2);
	MCUCR = (1 << ISC01);
	GICR = (1 << INT0);
	sei();
	for (;;)
		PORTB = PINC;
}
