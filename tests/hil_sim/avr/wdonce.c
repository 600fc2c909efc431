/* wdonce.c -- arm the watchdog once and never touch it again.
 *
 * Each boot writes MCUCSR | 0x80 to PORTA (one pin-log record per boot) and
 * the WDTCR the reset left to PORTC.  The first boot arms a 15 ms watchdog;
 * after the watchdog reset the program arms it again and turns it off with
 * the timed sequence while WDRF is still set.  On the ATmega162 the reset
 * leaves WDTCR = 0 and WDRF does not hold WDE, so there are two boots in all
 * (a part that re-arms the watchdog on reset would reboot every 16 ms). */
#include <avr/interrupt.h>
#include <avr/io.h>
#include <avr/sleep.h>
#include <avr/wdt.h>

int main(void)
{
	uint8_t flags = MCUCSR;
	DDRA = 0xFF;
	DDRC = 0xFF;
	PORTC = WDTCR;
	PORTA = flags | 0x80;
	wdt_enable(WDTO_15MS);
	if (flags & (1 << WDRF))
		wdt_disable(); /* WDRF still set */
	sei();
	sleep_enable();
	for (;;)
		sleep_cpu();
}
