/* idle.c -- what idle HexBot firmware looks like to the simulator: a 10 ms
 * timer tick (timer1 CTC) toggles PA0, a USART0 receive interrupt copies
 * bytes to PORTC, and the rest of the time the CPU sleeps in idle mode. */
#include <avr/interrupt.h>
#include <avr/io.h>
#include <avr/sleep.h>

volatile uint16_t ticks;

ISR(TIMER1_COMPA_vect)
{
	ticks++;
	PORTA ^= 1;
}

ISR(USART0_RXC_vect)
{
	PORTC = UDR0;
}

int main(void)
{
	DDRA = 0x01;
	DDRC = 0xFF;
	UBRR0L = 12;
	UCSR0B = (1 << RXEN0) | (1 << RXCIE0);
	OCR1A = 10000 - 1; /* 10 ms at 1 MHz */
	TCCR1B = (1 << WGM12) | (1 << CS10);
	TIMSK = (1 << OCIE1A);
	set_sleep_mode(SLEEP_MODE_IDLE);
	sei();
	for (;;) {
		sleep_enable();
		sleep_cpu();
		sleep_disable();
	}
}
