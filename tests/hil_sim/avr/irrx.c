/* irrx.c -- a receiver on the core's IR medium whose firmware switches its
 * USART1 receiver on and off (hil_sim/core/ir_medium.c).
 *
 * As irnode.c: the IR selector lines PA0..PA2 follow PC0..PC2, USART1 at
 * 300 8N1 (UBRR 207), every byte received is reported on USART0 (4800 8N1)
 * as two bytes, 0x80 | FE, data.  Besides, RXEN1 follows PC3: set while
 * PC3 is low, cleared while it is high (the test drives it with set_input). */
#include <avr/io.h>
#include "hw.h"

static void report(uint8_t b)
{
	while (!(UCSR0A & (1 << UDRE0)))
		;
	UDR0 = b;
}

int main(void)
{
	DDRA = 0x07;
	PORTA = PINC & 0x07;
	HW_UBRR0H_WRITE(0);
	UBRR0L = 12;
	HW_UCSR0C_WRITE((1 << UCSZ01) | (1 << UCSZ00));
	UCSR0B = (1 << TXEN0);
	HW_UBRR1H_WRITE(0);
	UBRR1L = 207;
	HW_UCSR1C_WRITE((1 << UCSZ11) | (1 << UCSZ10));
	uint8_t off = 0xFF; /* not yet written */
	for (;;) {
		uint8_t in = PINC;
		PORTA = in & 0x07;
		uint8_t want = in & 0x08;
		if (want != off) {
			off = want;
			UCSR1B = (off ? 0 : (1 << RXEN1)) | (1 << TXEN1);
		}
		if (UCSR1A & (1 << RXC1)) {
			uint8_t fe = (UCSR1A & (1 << FE1)) ? 1 : 0;
			uint8_t b = UDR1;
			report(0x80 | fe);
			report(b);
		}
	}
}
