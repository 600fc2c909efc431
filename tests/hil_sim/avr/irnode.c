/* irnode.c -- one end of the core's IR medium (hil_sim/core/ir_medium.c).
 *
 * The IR selector lines PA0..PA2 follow PC0..PC2 (driven by the test with
 * set_input), so the test moves the selector while the program runs.
 * USART1 at 300 8N1 (UBRR from EEPROM byte 2, 0xFF: 207); at start it sends
 * EEPROM bytes 0 and 1 (0xFF: none), back to back; EEPROM byte 3 = 0 leaves
 * the receiver off (RXEN clear).  Every byte received on USART1 is reported on USART0 (4800 8N1) as two bytes: 0x80 | FE, data. */
#include <avr/eeprom.h>
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
	uint8_t ubrr = eeprom_read_byte((const uint8_t *)2);
	HW_UBRR1H_WRITE(0);
	UBRR1L = ubrr == 0xFF ? 207 : ubrr;
	HW_UCSR1C_WRITE((1 << UCSZ11) | (1 << UCSZ10));
	uint8_t rx = eeprom_read_byte((const uint8_t *)3) ? (1 << RXEN1) : 0;
	UCSR1B = rx | (1 << TXEN1);
	for (uint8_t i = 0; i < 2; i++) {
		uint8_t b = eeprom_read_byte((const uint8_t *)(uint16_t)i);
		if (b == 0xFF)
			break;
		while (!(UCSR1A & (1 << UDRE1)))
			;
		UDR1 = b;
	}
	for (;;) {
		PORTA = PINC & 0x07;
		if (UCSR1A & (1 << RXC1)) {
			uint8_t fe = (UCSR1A & (1 << FE1)) ? 1 : 0;
			uint8_t b = UDR1;
			report(0x80 | fe);
			report(b);
		}
	}
}
