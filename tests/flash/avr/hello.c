/* Test image for the ISP tests: prints "HELLO <VERSION>" on USART1
 * (4800 baud 8N1 at 1 MHz, the control board's debug port), then idles. */
#include <avr/io.h>

#ifndef VERSION
#define VERSION "0"
#endif

static void put(char c)
{
	while (!(UCSR1A & (1 << UDRE1)))
		;
	UDR1 = c;
}

int main(void)
{
	UBRR1H = 0; /* URSEL1 = 0: this write reaches UBRR1H */
	UBRR1L = 12;
	UCSR1C = (1 << URSEL1) | (1 << UCSZ11) | (1 << UCSZ10);
	UCSR1B = (1 << TXEN1);
	for (const char *s = "HELLO " VERSION "\n\r"; *s; s++)
		put(*s);
	for (;;)
		;
}
