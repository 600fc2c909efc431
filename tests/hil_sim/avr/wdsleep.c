/* wdsleep.c -- "reboot by watchdog": arm a 15 ms watchdog, disable
 * interrupts and sleep.  Only the watchdog can end that sleep.  After the
 * reset: PORTA = 0xE0 and stop for good (sleep, interrupts off, no WDT). */
#include <avr/interrupt.h>
#include <avr/io.h>
#include <avr/sleep.h>
#include <avr/wdt.h>

int main(void)
{
	DDRA = 0xFF;
	if (MCUCSR & (1 << WDRF)) {
		MCUCSR = 0;
		wdt_disable();
		PORTA = 0xE0;
	} else {
		PORTA = 0x01;
		wdt_enable(WDTO_15MS);
	}
	cli();
	sleep_enable();
	sleep_cpu();
	for (;;)
		;
}
