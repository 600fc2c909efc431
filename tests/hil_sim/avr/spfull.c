/* spfull.c -- moves SP to 0x00FF (stack completely full, still legal) the way
 * gcc does, SPH first: for an instruction SP reads 0x0005.  Must not count as
 * a stack overflow. */
#include <avr/io.h>

int main(void)
{
	DDRB = 0xFF;
	__asm__ volatile(
		"cli\n\t"
		"ldi r24, 0x01\n\t" "out %[sph], r24\n\t"
		"ldi r24, 0x05\n\t" "out %[spl], r24\n\t"
		"ldi r24, 0x00\n\t" "out %[sph], r24\n\t"
		"ldi r24, 0xFF\n\t" "out %[spl], r24\n\t"
		:: [sph] "I"(_SFR_IO_ADDR(SPH)), [spl] "I"(_SFR_IO_ADDR(SPL)) : "r24");
	PORTB = 0x01;
	for (;;)
		;
}
