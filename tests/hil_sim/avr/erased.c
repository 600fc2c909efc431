/* erased.c -- jumps into erased flash (0xFFFF words) and runs off its end. */
#include <avr/io.h>

int main(void)
{
	DDRB = 0xFF;
	PORTB = 0x01;
	((void (*)(void))0x1000)(); /* word address 0x1000 = byte 0x2000: erased */
	PORTB = 0x02;
	for (;;)
		;
}
