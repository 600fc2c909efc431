/* cpuloop.c -- pure CPU work (CRC-16 over a counter), a PORTB write every
 * 1000 steps.  No peripheral involved, so every core must show the PORTB
 * writes at the same cycles; also the "busy MCU" of the benchmark. */
#include <avr/io.h>
#include <util/crc16.h>

int main(void)
{
	DDRB = 0xFF;
	uint16_t crc = 0xFFFF;
	for (;;) {
		for (uint16_t i = 0; i < 1000; i++)
			crc = _crc16_update(crc, (uint8_t)i);
		PORTB = (uint8_t)crc;
	}
}
