/* pinger.c -- the other end of echo.c on a USART0 wire (4800 8N1): sends 1,
 * and answers every byte r it receives with r + 1 until r reaches 20.
 * Each received byte is shown on PORTC. */
#include <avr/io.h>
#include "hw.h"

static void put(uint8_t b)
{
	while (!(UCSR0A & (1 << UDRE0)))
		;
	UDR0 = b;
}

int main(void)
{
	DDRC = 0xFF;
	HW_UBRR0H_WRITE(0);
	UBRR0L = 12;
	HW_UCSR0C_WRITE((1 << UCSZ01) | (1 << UCSZ00));
	UCSR0B = (1 << RXEN0) | (1 << TXEN0);
	put(1);
	for (;;) {
		while (!(UCSR0A & (1 << RXC0)))
			;
		uint8_t r = UDR0;
		PORTC = r;
		if (r < 20)
			put(r + 1);
	}
}
