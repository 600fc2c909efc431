/* spdrop.c -- SP set below SRAM, then straight-line code: the simulator must
 * stop the MCU within four instructions, at a PC just after sp_dropped
 * (test_core_edges.py). */
#include <avr/io.h>

int main(void)
{
	__asm__ volatile(
		"ldi r16, 0\n\t"
		"out %[sph], r16\n\t"   /* SP = 0x00FF: the last I/O address, still allowed */
		"ldi r16, 0x40\n\t"
		"out %[spl], r16\n"     /* SP = 0x0040: inside the I/O registers */
		".global sp_dropped\n"
		"sp_dropped:\n\t"
		".rept 64\n\tnop\n\t.endr\n"
		"1: rjmp 1b\n"
		:: [sph] "I" (_SFR_IO_ADDR(SPH)), [spl] "I" (_SFR_IO_ADDR(SPL)) : "r16");
	return 0;
}
