/* slow.c -- a receiver configured for 2400 baud on USART0 (UBRR = 25):
 * copies each byte to PORTB and its FE0 flag to PORTA. */
#include <avr/io.h>
#include "hw.h"

int main(void)
{
	DDRA = 0xFF;
	DDRB = 0xFF;
	UBRR0L = 25;
	UCSR0B = (1 << RXEN0);
	for (;;) {
		while (!(UCSR0A & (1 << RXC0)))
			;
		PORTA = UCSR0A & (1 << FE0); /* read FE before UDR, as the datasheet says */
		PORTB = UDR0;
	}
}
