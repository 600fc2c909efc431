/* badop.c -- runs into an opcode the AVR does not have (0x0001), after
 * showing on PORTB that it started. */
#include <avr/io.h>

int main(void)
{
	DDRB = 0xFF;
	PORTB = 0x01;
	__asm__ volatile(".word 0x0001");
	PORTB = 0x02;
	for (;;)
		;
}
