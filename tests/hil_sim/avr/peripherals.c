/* peripherals.c -- touches every peripheral the ATmega162 core models and
 * reports what happened, so the same program can run on our core and on
 * simavr's stock atmega128 core and the traces be compared.
 *
 * PORTA event codes (the pin log shows when each happened):
 *   0x01 start            ((n+1)<<4)|t  timer n interrupt, tick t = 1..3
 *   0x2F before INT0 edge 0x20 INT0 interrupt
 *   0x3E SPI write        0x3F SPIF seen
 *   0x40 all done, watchdog armed, sleeping
 *   0xE0 restarted by the watchdog (then stops: sleep with interrupts off)
 * PORTC: EEPROM byte read back; on the ATmega162 then UCSR0C read back
 *        through the two-read URSEL sequence.
 * USART0 (4800 8N1, UDRE interrupt): "PER"; USART1 (4800 8N1, polled): "!".
 */
#include <avr/eeprom.h>
#include <avr/interrupt.h>
#include <avr/io.h>
#include <avr/sleep.h>
#include <avr/wdt.h>
#include "hw.h"

static volatile uint8_t ticks[4];
static volatile uint8_t done;
static const char message[] = "PER";
static volatile uint8_t tx_pos;

static void tick(uint8_t n, volatile uint8_t *tccr, uint8_t stop_mask)
{
	uint8_t t = ++ticks[n];
	PORTA = (uint8_t)((n + 1) << 4) | t;
	if (t == 3) {
		*tccr &= (uint8_t)~stop_mask; /* stop the clock */
		done |= (uint8_t)(1 << n);
	}
}

ISR(TIMER0_OVF_vect) { tick(0, &TCCR0, 7); }
ISR(TIMER1_COMPA_vect) { tick(1, &TCCR1B, 7); }
ISR(TIMER2_OVF_vect) { tick(2, &TCCR2, 7); }
ISR(TIMER3_COMPA_vect) { tick(3, &TCCR3B, 7); }

ISR(INT0_vect)
{
	PORTA = 0x20;
	done |= 0x10;
}

ISR(HW_UDRE0_vect)
{
	if (tx_pos < sizeof message - 1)
		UDR0 = message[tx_pos++];
	else
		UCSR0B &= (uint8_t)~(1 << UDRIE0);
}

int main(void)
{
	DDRA = 0xFF;
	DDRC = 0xFF;
	if (HW_MCUSR & (1 << WDRF)) {
		HW_MCUSR = 0;
		wdt_disable();
		PORTA = 0xE0;
		cli();
		sleep_enable();
		sleep_cpu(); /* interrupts off: the simulator calls this "done" */
	}
	PORTA = 0x01;

	/* USARTs: 4800 8N1 */
	HW_UBRR0H_WRITE(0);
	UBRR0L = 12;
	HW_UCSR0C_WRITE((1 << UCSZ01) | (1 << UCSZ00));
	UCSR0B = (1 << TXEN0) | (1 << UDRIE0);
	HW_UBRR1H_WRITE(0);
	UBRR1L = 12;
	HW_UCSR1C_WRITE((1 << UCSZ11) | (1 << UCSZ10));
	UCSR1B = (1 << TXEN1);

	/* four timers, three ticks each */
	TCCR0 = (1 << CS01);                  /* normal, clk/8: 2048 cycles */
	OCR1A = 5000 - 1;
	TCCR1B = (1 << WGM12) | (1 << CS10);  /* CTC, clk/1: 5000 cycles */
	TCCR2 = (1 << CS21);                  /* normal, clk/8: 2048 cycles */
	OCR3A = 1000 - 1;
	TCCR3B = (1 << WGM32) | (1 << CS31);  /* CTC, clk/8: 8000 cycles */
	TIMSK = (1 << TOIE0) | (1 << OCIE1A) | (1 << TOIE2);
	ETIMSK = (1 << OCIE3A);
	sei();

	/* EEPROM */
	eeprom_write_byte((uint8_t *)0x10, 0x5A);
	PORTC = eeprom_read_byte((const uint8_t *)0x10);

	/* INT0 from our own pin: external interrupts see output pins too */
	DDRD |= (1 << HW_INT0_PIN);
	PORTD |= (1 << HW_INT0_PIN);
	HW_INT0_FALLING();
	HW_INT0_ENABLE();
	PORTA = 0x2F;
	PORTD &= (uint8_t)~(1 << HW_INT0_PIN);

	/* SPI master, clk/16 */
	DDRB |= (1 << PB5) | (1 << PB7) | (1 << PB4);
	SPCR = (1 << SPE) | (1 << MSTR) | (1 << SPR0);
	PORTA = 0x3E;
	SPDR = 0xA5;
	while (!(SPSR & (1 << SPIF)))
		;
	PORTA = 0x3F;

	while (!(UCSR1A & (1 << UDRE1)))
		;
	UDR1 = '!';

#if defined(__AVR_ATmega162__)
	cli();
	uint8_t h = UBRR0H;  /* first read: UBRR0H */
	uint8_t c = UCSR0C;  /* read in the very next cycle: UCSR0C */
	sei();
	PORTC = h;
	PORTC = c;
#endif

	set_sleep_mode(SLEEP_MODE_IDLE);
	while (done != 0x1F)
		sleep_mode();
	PORTA = 0x40;
	wdt_enable(WDTO_15MS);
	for (;;)
		sleep_mode(); /* nothing wakes us: the watchdog resets the part */
}
