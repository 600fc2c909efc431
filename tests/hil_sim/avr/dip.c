/* dip.c -- inputs: PORTC pull-ups on, PINC copied to PORTB continuously
 * (the module-id DIP switches); INT0 (PD2, pull-up, falling edge) counts on
 * PORTA bits 0..3, INT2 (PE0, falling edge) on PORTA bits 4..7; pin changes
 * on PORTC (PCINT8..15) count on PE1..PE2. */
#include <avr/interrupt.h>
#include <avr/io.h>

ISR(INT0_vect)
{
	PORTA++;
}

ISR(INT2_vect)
{
	PORTA += 0x10;
}

ISR(PCINT1_vect)
{
	PORTE = (uint8_t)(((PORTE + 2) & 0x06) | (1 << PE0)); /* keep the PE0 pull-up */
}

int main(void)
{
	DDRA = 0xFF;
	DDRB = 0xFF;
	PORTC = 0xFF;
	DDRE = 0x06;
	PORTD = (1 << PD2);
	PORTE = (1 << PE0);
	MCUCR = (1 << ISC01);
	EMCUCR = 0; /* ISC2 = 0: falling edge */
	PCMSK1 = 0xFF;
	GIFR = (1 << INTF2) | (1 << PCIF1);
	GICR = (1 << INT0) | (1 << INT2) | (1 << PCIE1);
	sei();
	for (;;)
		PORTB = PINC;
}
