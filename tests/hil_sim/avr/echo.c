/* echo.c -- USART smoke test.
 * USART0: 4800 8N1 (set through URSEL), echoes every byte + 1 and shows the
 * byte on PORTB.  USART1: 300 8N1, sends 'H' once at start-up. */
#include <avr/io.h>
#include "hw.h"

int main(void)
{
	DDRB = 0xFF;
	HW_UBRR0H_WRITE(0);
	UBRR0L = 12; /* 1 MHz / (16 * 13) = 4808 baud */
	HW_UCSR0C_WRITE((1 << UCSZ01) | (1 << UCSZ00));
	UCSR0B = (1 << RXEN0) | (1 << TXEN0);

	HW_UBRR1H_WRITE(207 >> 8);
	UBRR1L = 207; /* 1 MHz / (16 * 208) = 300.5 baud */
	HW_UCSR1C_WRITE((1 << UCSZ11) | (1 << UCSZ10));
	UCSR1B = (1 << TXEN1);
	UDR1 = 'H';

	for (;;) {
		while (!(UCSR0A & (1 << RXC0)))
			;
		uint8_t b = UDR0;
		PORTB = b;
		while (!(UCSR0A & (1 << UDRE0)))
			;
		UDR0 = b + 1;
	}
}
