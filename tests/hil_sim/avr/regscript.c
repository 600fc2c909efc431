/* regscript.c -- runs a register script from EEPROM, for edge tests of the
 * core (tests/hil_sim/test_core_edges.py).  Timer 1 counts every cycle from
 * the start; each script step is a letter and its operands:
 *   W a v   write v to data address a
 *   R a     record the byte at data address a
 *   P a m   wait until (byte at a) & m == m;  Z a m: until it is 0
 *   T       record TCNT1 (low, high)
 *   S / C   sei / cli
 *   L       the SLEEP instruction (sleep_cpu), SE as the script left it
 *   Q a v b m  write v to a, wait until (byte at b) & m == m, record the
 *           cycles that took (TCNT1 difference, low, high)
 *   F h l   clock the 16-bit word h:l out to an RF12 on port B (nSEL PB4,
 *           SDI PB5, SDO PB6, SCK PB7; DDRB and nSEL high set up before),
 *           MSB first, and record the 16 bits read from SDO (low, high)
 *   G x h l the same with 24 bits (x first), recording the last 16 read
 *   .       end: sleep (idle) for good, interrupts still served
 * Records go to rec[] (rec_len of them); the USART0 RXC interrupt reads UDR0
 * and records 'r', the byte and TCNT1 (low, high); the UDRE interrupt
 * records 'u' and TCNT1 and switches UDRIE off. */
#include <avr/eeprom.h>
#include <avr/interrupt.h>
#include <avr/io.h>
#include <avr/sleep.h>

volatile uint8_t rec[96];
volatile uint8_t rec_len;

static void put(uint8_t v)
{
	if (rec_len < sizeof rec)
		rec[rec_len++] = v;
}

static uint8_t ee(uint16_t *pc)
{
	return eeprom_read_byte((const uint8_t *)(*pc)++);
}

static void put_time(uint16_t t)
{
	put((uint8_t)t);
	put((uint8_t)(t >> 8));
}

ISR(USART0_RXC_vect)
{
	uint16_t t = TCNT1;
	put('r');
	put(UDR0);
	put_time(t);
}

ISR(USART0_UDRE_vect)
{
	uint16_t t = TCNT1;
	put('u');
	put_time(t);
	UCSR0B &= ~(1 << UDRIE0);
}

int main(void)
{
	TCCR1B = 1 << CS10; /* timer 1 at the CPU clock */
	uint16_t pc = 0;
	for (;;) {
		uint8_t op = ee(&pc);
		if (op == 'W') {
			uint8_t a = ee(&pc), v = ee(&pc);
			*(volatile uint8_t *)(uint16_t)a = v;
		} else if (op == 'R') {
			uint8_t a = ee(&pc);
			put(*(volatile uint8_t *)(uint16_t)a);
		} else if (op == 'P' || op == 'Z') {
			uint8_t a = ee(&pc), m = ee(&pc);
			if (op == 'P')
				while ((*(volatile uint8_t *)(uint16_t)a & m) != m)
					;
			else
				while (*(volatile uint8_t *)(uint16_t)a & m)
					;
		} else if (op == 'Q') {
			uint8_t a = ee(&pc), v = ee(&pc), b = ee(&pc), m = ee(&pc);
			volatile uint8_t *flag = (volatile uint8_t *)(uint16_t)b;
			uint16_t t0 = TCNT1;
			*(volatile uint8_t *)(uint16_t)a = v;
			while ((*flag & m) != m)
				;
			put_time(TCNT1 - t0);
		} else if (op == 'F' || op == 'G') {
			uint32_t w = op == 'G' ? (uint32_t)ee(&pc) << 16 : 0;
			w |= (uint16_t)ee(&pc) << 8;
			w |= ee(&pc);
			uint16_t in = 0;
			PORTB &= ~(1 << PB4);
			for (int8_t k = op == 'G' ? 23 : 15; k >= 0; k--) {
				if (w & (1ul << k))
					PORTB |= 1 << PB5;
				else
					PORTB &= ~(1 << PB5);
				PORTB |= 1 << PB7;
				in = (in << 1) | ((PINB >> PB6) & 1);
				PORTB &= ~(1 << PB7);
			}
			PORTB |= 1 << PB4;
			put_time(in);
		} else if (op == 'T') {
			uint8_t lo = TCNT1L;
			put(lo);
			put(TCNT1H);
		} else if (op == 'S') {
			sei();
		} else if (op == 'C') {
			cli();
		} else if (op == 'L') {
			sleep_cpu();
		} else {
			break;
		}
	}
	set_sleep_mode(SLEEP_MODE_IDLE);
	for (;;) {
		sleep_enable();
		sei();
		sleep_cpu();
	}
}
