/* stack.c -- unbounded recursion: the stack grows down out of SRAM into the
 * I/O registers.  A real part would run wild; the simulator must say so. */
#include <avr/io.h>

volatile uint8_t sink;

__attribute__((noinline)) uint16_t dive(uint16_t n)
{
	volatile uint8_t pad[8];
	pad[0] = (uint8_t)n;
	sink = pad[0];
	return dive(n + 1) + pad[0];
}

int main(void)
{
	DDRB = 0xFF;
	PORTB = 0x01;
	return dive(0);
}
