/*
 * m162_core.c -- the ATmega162 as a simavr core.
 *
 * Like simavr's cores/sim_mega128.c this file is mostly data: one struct of
 * peripheral descriptors filled from avr-libc's register map (avr/iom162.h).
 * Debian's libsimavr-dev does not install simavr's sim_core_declare.h, so the
 * few macros it provides are defined here.
 *
 * Departures from a stock simavr core, each explained where it is done:
 *  - UBRRnH/UCSRnC share one I/O address (URSEL selects); both live at
 *    reserved data addresses 0xF8..0xFB and m162_usart.c routes accesses.
 *  - A "fixup" I/O module registered first, so its reset runs after every
 *    simavr module's reset, undoes simavr's debug defaults (TXEN on at reset).
 *  - PINx writes do nothing (the ATmega162 predates the PIN-toggle feature).
 *  - Our own run function: SLEEP honours MCUCR.SE, sleeping advances cycles
 *    only (no wall-clock wait) and never past the current lock-step quantum.
 *  - Interrupts as the datasheet has them: one instruction after SEI/RETI
 *    (simavr 1.6: two), "sei; sleep" sleeps and the pending interrupt wakes
 *    it (simavr: SLEEP declined), and a wake-up halts the core four cycles.
 *  - Watchdog: WDTCR = 0 after every reset, and WDRF does not hold WDE set
 *    (ATmega162 datasheet, safety level 1; simavr re-arms it after a
 *    watchdog reset, as the newer parts do).
 *  - Timers 0..3: a TCNT write or a clock start counts from the written
 *    value on the next edge of the free-running prescaler (simavr rescales
 *    the value by 255 and drops the prescaler phase: a 10 ms tick came out
 *    9,976 cycles instead of 9,984; and it loses a 16-bit TCNT written while
 *    the timer is stopped).
 *  - Each MCU runs on its own clock (m162_clock_t); what it reports to the
 *    scheduler is in cluster cycles.
 */
#include <stdlib.h>
#include <string.h>
#include <fcntl.h>
#include <unistd.h>
#include <gelf.h>
#include <libelf.h>
#include <stdio.h>
#include <stdarg.h>
#include <stddef.h>

#include "grow.h"
#include "m162.h"
#include "hexbot_codes.h"
#include "sim_elf.h"
#include "sim_core.h"
#include "sim_vcd_file.h"
#include "sim_core_config.h"

/* The macros sim_core_declare.h would give us: register names from avr-libc
 * evaluate to data-space addresses, vectors and bits to plain numbers. */
#define _AVR_IO_H_
#define __ASSEMBLER__
#define __AVR_LIBC_DEPRECATED_ENABLE__
#define _SFR_IO8(v) ((v) + 32)
#define _SFR_IO16(v) ((v) + 32)
#define _SFR_MEM8(v) (v)
#define _SFR_MEM16(v) (v)
#define _BV(v) (v)
#define _VECTOR(v) (v)
#include "/usr/lib/avr/include/avr/iom162.h"

/* Reserved extended-I/O addresses holding the two halves of each shared
 * UBRRnH/UCSRnC location (unused on the real part). */
#define M162_UBRR0H_SHADOW 0xF8
#define M162_UCSR0C_SHADOW 0xF9
#define M162_UBRR1H_SHADOW 0xFA
#define M162_UCSR1C_SHADOW 0xFB

/* HexBot boards: internal RC / 8 = 1 MHz, JTAG off so PC4..PC7 are I/O
 * (thesis Table 3-6, from the generated protocol header).  avr-libc's
 * factory default high fuse is 0x99. */
#define M162_LFUSE HB_FUSE_LOW
#define M162_HFUSE HB_FUSE_HIGH
#define M162_EFUSE HB_FUSE_EXTENDED

const uint16_t m162_port_regs[M162_NPORTS][3] = {
	{ PINA, DDRA, PORTA }, { PINB, DDRB, PORTB }, { PINC, DDRC, PORTC },
	{ PIND, DDRD, PORTD }, { PINE, DDRE, PORTE },
};

static void m162_init(avr_t *avr);

/* ------------------------------------------------------------------ */
/* clock */

uint64_t m162_to_local(const m162_t *m, uint64_t cluster_cycle)
{
	const m162_clock_t *k = &m->clock;
	if (k->hz == k->nominal_hz || cluster_cycle <= k->base_cluster)
		return k->base_local + (cluster_cycle - k->base_cluster);
	unsigned __int128 d = (unsigned __int128)(cluster_cycle - k->base_cluster) * k->hz;
	return k->base_local + (uint64_t)(d / k->nominal_hz);
}

uint64_t m162_to_cluster(const m162_t *m, uint64_t local_cycle)
{
	const m162_clock_t *k = &m->clock;
	if (k->hz == k->nominal_hz || local_cycle <= k->base_local)
		return k->base_cluster + (local_cycle - k->base_local);
	unsigned __int128 d = (unsigned __int128)(local_cycle - k->base_local) * k->nominal_hz;
	return k->base_cluster + (uint64_t)((d + k->hz - 1) / k->hz);
}

double m162_bit_time(const m162_t *m, uint32_t local_cycles)
{
	const m162_clock_t *k = &m->clock;
	if (k->hz == k->nominal_hz)
		return (double)local_cycles;
	return (double)((uint64_t)local_cycles * k->nominal_hz) / (double)k->hz;
}

void m162_set_clock(m162_t *m, uint32_t hz, uint64_t now)
{
	uint64_t local = m162_to_local(m, now);
	m->clock.base_local = local;
	m->clock.base_cluster = now;
	m->clock.hz = hz;
	/* baud rates and the watchdog's cycle count follow the real clock */
	m->avr->frequency = hz;
}
static void m162_core_reset(avr_t *avr);
static void m162_extint_level(m162_t *m);

#define M162_USART(_n, _ubrrh, _ucsrc) \
	.uart ## _n = { \
		.name = '0' + _n, \
		.r_udr = UDR ## _n, \
		.fe = AVR_IO_REGBIT(UCSR ## _n ## A, FE ## _n), \
		.dor = AVR_IO_REGBIT(UCSR ## _n ## A, DOR ## _n), \
		.upe = AVR_IO_REGBIT(UCSR ## _n ## A, UPE ## _n), \
		.u2x = AVR_IO_REGBIT(UCSR ## _n ## A, U2X ## _n), \
		.txen = AVR_IO_REGBIT(UCSR ## _n ## B, TXEN ## _n), \
		.rxen = AVR_IO_REGBIT(UCSR ## _n ## B, RXEN ## _n), \
		.rxb8 = AVR_IO_REGBIT(UCSR ## _n ## B, RXB8 ## _n), \
		.usbs = AVR_IO_REGBIT(_ucsrc, USBS ## _n), \
		.ucsz = AVR_IO_REGBITS(_ucsrc, UCSZ ## _n ## 0, 0x3), \
		.ucsz2 = AVR_IO_REGBIT(UCSR ## _n ## B, UCSZ ## _n ## 2), \
		.ubrrl = AVR_IO_REGBITS(UBRR ## _n ## L, 0, 0xFF), \
		.ubrrh = AVR_IO_REGBITS(_ubrrh, 0, 0xF), \
		.r_ucsra = UCSR ## _n ## A, \
		.r_ucsrb = UCSR ## _n ## B, \
		.r_ucsrc = _ucsrc, \
		.rxc = { \
			.enable = AVR_IO_REGBIT(UCSR ## _n ## B, RXCIE ## _n), \
			.raised = AVR_IO_REGBIT(UCSR ## _n ## A, RXC ## _n), \
			.vector = USART ## _n ## _RXC_vect, \
			.raise_sticky = 1, \
		}, \
		.txc = { \
			.enable = AVR_IO_REGBIT(UCSR ## _n ## B, TXCIE ## _n), \
			.raised = AVR_IO_REGBIT(UCSR ## _n ## A, TXC ## _n), \
			.vector = USART ## _n ## _TXC_vect, \
		}, \
		.udrc = { \
			.enable = AVR_IO_REGBIT(UCSR ## _n ## B, UDRIE ## _n), \
			.raised = AVR_IO_REGBIT(UCSR ## _n ## A, UDRE ## _n), \
			.vector = USART ## _n ## _UDRE_vect, \
			.raise_sticky = 1, \
		}, \
	}

#define M162_PORT(_l, _c, _u) \
	.port ## _l = { .name = _c, .r_port = PORT ## _u, .r_ddr = DDR ## _u, .r_pin = PIN ## _u }

/* 16-bit timer wave modes shared by timers 1 and 3 (same table as simavr's
 * megax4 timer1). */
#define M162_WGM16 { \
	[0] = AVR_TIMER_WGM_NORMAL16(), \
	[1] = AVR_TIMER_WGM_FCPWM8(), [2] = AVR_TIMER_WGM_FCPWM9(), \
	[3] = AVR_TIMER_WGM_FCPWM10(), [4] = AVR_TIMER_WGM_CTC(), \
	[5] = AVR_TIMER_WGM_FASTPWM8(), [6] = AVR_TIMER_WGM_FASTPWM9(), \
	[7] = AVR_TIMER_WGM_FASTPWM10(), [12] = AVR_TIMER_WGM_ICCTC(), \
	[14] = AVR_TIMER_WGM_ICPWM(), [15] = AVR_TIMER_WGM_OCPWM(), }

static const struct mcu_t mcu_mega162 = {
	.core = {
		.mmcu = "atmega162",
		.ioend = RAMSTART - 1,
		.ramend = RAMEND,
		.flashend = FLASHEND,
		.e2end = E2END,
		.vector_size = 4,
		.fuse = { M162_LFUSE, M162_HFUSE, M162_EFUSE },
		.signature = { SIGNATURE_0, SIGNATURE_1, SIGNATURE_2 },
		.lockbits = 0xFF,
		.reset_flags = {
			.porf = AVR_IO_REGBIT(MCUCSR, PORF),
			.extrf = AVR_IO_REGBIT(MCUCSR, EXTRF),
			.borf = AVR_IO_REGBIT(MCUCSR, BORF),
			.wdrf = AVR_IO_REGBIT(MCUCSR, WDRF),
		},
		.init = m162_init,
		.reset = m162_core_reset,
	},
	AVR_EEPROM_DECLARE_NOEEPM(EE_RDY_vect),
	AVR_SELFPROG_DECLARE(SPMCR, SPMEN, SPM_RDY_vect),
	/* No watchdog interrupt on this part: bits 6/7 of WDTCR are reserved and
	 * read 0, so the "interrupt mode" of simavr's model never engages. */
	.watchdog = {
		.wdrf = AVR_IO_REGBIT(MCUCSR, WDRF),
		.wdce = AVR_IO_REGBIT(WDTCR, WDCE),
		.wde = AVR_IO_REGBIT(WDTCR, WDE),
		.wdp = { AVR_IO_REGBIT(WDTCR, WDP0), AVR_IO_REGBIT(WDTCR, WDP1),
				AVR_IO_REGBIT(WDTCR, WDP2) },
		.watchdog = {
			.enable = AVR_IO_REGBIT(WDTCR, 6),
			.raised = AVR_IO_REGBIT(WDTCR, 7),
			.vector = 0,
		},
	},
	.extint = {
		.eint[0] = {
			.port_ioctl = AVR_IOCTL_IOPORT_GETIRQ('D'), .port_pin = PD2,
			.isc = { AVR_IO_REGBIT(MCUCR, ISC00), AVR_IO_REGBIT(MCUCR, ISC01) },
			.vector = { .enable = AVR_IO_REGBIT(GICR, INT0),
				.raised = AVR_IO_REGBIT(GIFR, INTF0), .vector = INT0_vect },
		},
		.eint[1] = {
			.port_ioctl = AVR_IOCTL_IOPORT_GETIRQ('D'), .port_pin = PD3,
			.isc = { AVR_IO_REGBIT(MCUCR, ISC10), AVR_IO_REGBIT(MCUCR, ISC11) },
			.vector = { .enable = AVR_IO_REGBIT(GICR, INT1),
				.raised = AVR_IO_REGBIT(GIFR, INTF1), .vector = INT1_vect },
		},
		/* INT2 is asynchronous, edge only, one sense bit in EMCUCR */
		.eint[2] = {
			.port_ioctl = AVR_IOCTL_IOPORT_GETIRQ('E'), .port_pin = PE0,
			.isc = { AVR_IO_REGBIT(EMCUCR, ISC2) },
			.vector = { .enable = AVR_IO_REGBIT(GICR, INT2),
				.raised = AVR_IO_REGBIT(GIFR, INTF2), .vector = INT2_vect },
		},
	},
	.porta = {
		.name = 'A', .r_port = PORTA, .r_ddr = DDRA, .r_pin = PINA,
		.pcint = { .enable = AVR_IO_REGBIT(GICR, PCIE0),
			.raised = AVR_IO_REGBIT(GIFR, PCIF0), .vector = PCINT0_vect },
		.r_pcint = PCMSK0,
	},
	M162_PORT(b, 'B', B),
	.portc = {
		.name = 'C', .r_port = PORTC, .r_ddr = DDRC, .r_pin = PINC,
		.pcint = { .enable = AVR_IO_REGBIT(GICR, PCIE1),
			.raised = AVR_IO_REGBIT(GIFR, PCIF1), .vector = PCINT1_vect },
		.r_pcint = PCMSK1,
	},
	M162_PORT(d, 'D', D),
	M162_PORT(e, 'E', E),
	M162_USART(0, M162_UBRR0H_SHADOW, M162_UCSR0C_SHADOW),
	M162_USART(1, M162_UBRR1H_SHADOW, M162_UCSR1C_SHADOW),
	.timer0 = {
		.name = '0',
		.wgm = { AVR_IO_REGBIT(TCCR0, WGM00), AVR_IO_REGBIT(TCCR0, WGM01) },
		.wgm_op = {
			[0] = AVR_TIMER_WGM_NORMAL8(), [1] = AVR_TIMER_WGM_FCPWM8(),
			[2] = AVR_TIMER_WGM_CTC(), [3] = AVR_TIMER_WGM_FASTPWM8(),
		},
		.cs = { AVR_IO_REGBIT(TCCR0, CS00), AVR_IO_REGBIT(TCCR0, CS01),
				AVR_IO_REGBIT(TCCR0, CS02) },
		.cs_div = { 0, 0, 3 /* 8 */, 6 /* 64 */, 8 /* 256 */, 10 /* 1024 */,
				AVR_TIMER_EXTCLK_CHOOSE, AVR_TIMER_EXTCLK_CHOOSE },
		.ext_clock_pin = AVR_IO_REGBIT(PORTB, PB0), /* T0 */
		.r_tcnt = TCNT0,
		.overflow = { .enable = AVR_IO_REGBIT(TIMSK, TOIE0),
			.raised = AVR_IO_REGBIT(TIFR, TOV0), .vector = TIMER0_OVF_vect },
		.comp = {
			[AVR_TIMER_COMPA] = {
				.r_ocr = OCR0,
				.com = AVR_IO_REGBITS(TCCR0, COM00, 0x3),
				.com_pin = AVR_IO_REGBIT(PORTB, PB0), /* OC0 */
				.interrupt = { .enable = AVR_IO_REGBIT(TIMSK, OCIE0),
					.raised = AVR_IO_REGBIT(TIFR, OCF0), .vector = TIMER0_COMP_vect },
			},
		},
	},
	.timer1 = {
		.name = '1',
		.wgm = { AVR_IO_REGBIT(TCCR1A, WGM10), AVR_IO_REGBIT(TCCR1A, WGM11),
				AVR_IO_REGBIT(TCCR1B, WGM12), AVR_IO_REGBIT(TCCR1B, WGM13) },
		.wgm_op = M162_WGM16,
		.cs = { AVR_IO_REGBIT(TCCR1B, CS10), AVR_IO_REGBIT(TCCR1B, CS11),
				AVR_IO_REGBIT(TCCR1B, CS12) },
		.cs_div = { 0, 0, 3, 6, 8, 10, AVR_TIMER_EXTCLK_CHOOSE, AVR_TIMER_EXTCLK_CHOOSE },
		.ext_clock_pin = AVR_IO_REGBIT(PORTB, PB1), /* T1 */
		.r_tcnt = TCNT1L, .r_tcnth = TCNT1H,
		.r_icr = ICR1L, .r_icrh = ICR1H,
		.ices = AVR_IO_REGBIT(TCCR1B, ICES1),
		.icp = AVR_IO_REGBIT(PORTE, PE0), /* ICP1 */
		.overflow = { .enable = AVR_IO_REGBIT(TIMSK, TOIE1),
			.raised = AVR_IO_REGBIT(TIFR, TOV1), .vector = TIMER1_OVF_vect },
		.icr = { .enable = AVR_IO_REGBIT(TIMSK, TICIE1),
			.raised = AVR_IO_REGBIT(TIFR, ICF1), .vector = TIMER1_CAPT_vect },
		.comp = {
			[AVR_TIMER_COMPA] = {
				.r_ocr = OCR1AL, .r_ocrh = OCR1AH,
				.com = AVR_IO_REGBITS(TCCR1A, COM1A0, 0x3),
				.com_pin = AVR_IO_REGBIT(PORTD, PD5), /* OC1A */
				.interrupt = { .enable = AVR_IO_REGBIT(TIMSK, OCIE1A),
					.raised = AVR_IO_REGBIT(TIFR, OCF1A), .vector = TIMER1_COMPA_vect },
			},
			[AVR_TIMER_COMPB] = {
				.r_ocr = OCR1BL, .r_ocrh = OCR1BH,
				.com = AVR_IO_REGBITS(TCCR1A, COM1B0, 0x3),
				.com_pin = AVR_IO_REGBIT(PORTE, PE2), /* OC1B */
				.interrupt = { .enable = AVR_IO_REGBIT(TIMSK, OCIE1B),
					.raised = AVR_IO_REGBIT(TIFR, OCF1B), .vector = TIMER1_COMPB_vect },
			},
		},
	},
	.timer2 = {
		.name = '2',
		.wgm = { AVR_IO_REGBIT(TCCR2, WGM20), AVR_IO_REGBIT(TCCR2, WGM21) },
		.wgm_op = {
			[0] = AVR_TIMER_WGM_NORMAL8(), [1] = AVR_TIMER_WGM_FCPWM8(),
			[2] = AVR_TIMER_WGM_CTC(), [3] = AVR_TIMER_WGM_FASTPWM8(),
		},
		.cs = { AVR_IO_REGBIT(TCCR2, CS20), AVR_IO_REGBIT(TCCR2, CS21),
				AVR_IO_REGBIT(TCCR2, CS22) },
		/* timer2's prescaler has /32 and /128 steps */
		.cs_div = { 0, 0, 3 /* 8 */, 5 /* 32 */, 6 /* 64 */, 7 /* 128 */,
				8 /* 256 */, 10 /* 1024 */ },
		.as2 = AVR_IO_REGBIT(ASSR, AS2), /* 32 kHz crystal on TOSC1/2 */
		.r_tcnt = TCNT2,
		.overflow = { .enable = AVR_IO_REGBIT(TIMSK, TOIE2),
			.raised = AVR_IO_REGBIT(TIFR, TOV2), .vector = TIMER2_OVF_vect },
		.comp = {
			[AVR_TIMER_COMPA] = {
				.r_ocr = OCR2,
				.com = AVR_IO_REGBITS(TCCR2, COM20, 0x3),
				.com_pin = AVR_IO_REGBIT(PORTB, PB1), /* OC2 */
				.interrupt = { .enable = AVR_IO_REGBIT(TIMSK, OCIE2),
					.raised = AVR_IO_REGBIT(TIFR, OCF2), .vector = TIMER2_COMP_vect },
			},
		},
	},
	.timer3 = {
		.name = '3',
		.wgm = { AVR_IO_REGBIT(TCCR3A, WGM30), AVR_IO_REGBIT(TCCR3A, WGM31),
				AVR_IO_REGBIT(TCCR3B, WGM32), AVR_IO_REGBIT(TCCR3B, WGM33) },
		.wgm_op = M162_WGM16,
		.cs = { AVR_IO_REGBIT(TCCR3B, CS30), AVR_IO_REGBIT(TCCR3B, CS31),
				AVR_IO_REGBIT(TCCR3B, CS32) },
		/* no T3 pin: the last two steps are /16 and /32 */
		.cs_div = { 0, 0, 3 /* 8 */, 6 /* 64 */, 8 /* 256 */, 10 /* 1024 */,
				4 /* 16 */, 5 /* 32 */ },
		.r_tcnt = TCNT3L, .r_tcnth = TCNT3H,
		.r_icr = ICR3L, .r_icrh = ICR3H,
		.ices = AVR_IO_REGBIT(TCCR3B, ICES3),
		.icp = AVR_IO_REGBIT(PORTD, PD3), /* ICP3 */
		.overflow = { .enable = AVR_IO_REGBIT(ETIMSK, TOIE3),
			.raised = AVR_IO_REGBIT(ETIFR, TOV3), .vector = TIMER3_OVF_vect },
		.icr = { .enable = AVR_IO_REGBIT(ETIMSK, TICIE3),
			.raised = AVR_IO_REGBIT(ETIFR, ICF3), .vector = TIMER3_CAPT_vect },
		.comp = {
			[AVR_TIMER_COMPA] = {
				.r_ocr = OCR3AL, .r_ocrh = OCR3AH,
				.com = AVR_IO_REGBITS(TCCR3A, COM3A0, 0x3),
				.com_pin = AVR_IO_REGBIT(PORTD, PD4), /* OC3A */
				.interrupt = { .enable = AVR_IO_REGBIT(ETIMSK, OCIE3A),
					.raised = AVR_IO_REGBIT(ETIFR, OCF3A), .vector = TIMER3_COMPA_vect },
			},
			[AVR_TIMER_COMPB] = {
				.r_ocr = OCR3BL, .r_ocrh = OCR3BH,
				.com = AVR_IO_REGBITS(TCCR3A, COM3B0, 0x3),
				.com_pin = AVR_IO_REGBIT(PORTB, PB4), /* OC3B */
				.interrupt = { .enable = AVR_IO_REGBIT(ETIMSK, OCIE3B),
					.raised = AVR_IO_REGBIT(ETIFR, OCF3B), .vector = TIMER3_COMPB_vect },
			},
		},
	},
	AVR_SPI_DECLARE(0, 0),
};

/* ------------------------------------------------------------------ */
/* logging: simavr reports crashes and bad opcodes only through its logger */

static void m162_logger(avr_t *avr, const int level, const char *fmt, va_list ap)
{
	if (!avr || level > LOG_ERROR || !avr->custom.data)
		return;
	m162_t *m = m162_of(avr);
	char buf[256];
	vsnprintf(buf, sizeof buf, fmt, ap);
	/* strip simavr's colour codes and newlines */
	char clean[256];
	size_t j = 0;
	for (size_t i = 0; buf[i] && j + 1 < sizeof clean; i++) {
		if (buf[i] == '\x1b') {
			while (buf[i] && buf[i] != 'm')
				i++;
			if (!buf[i])
				break;
			continue;
		}
		if (buf[i] != '\n')
			clean[j++] = buf[i];
	}
	clean[j] = 0;
	if (level == LOG_ERROR) {
		if (!strcmp(clean, "avr_sadly_crashed")) {
			/* the specific reason, if any, was logged just before */
			if (avr->pc >= avr->flashend)
				snprintf(m->last_error, sizeof m->last_error,
						"program counter ran past the end of flash (PC=%04x)", avr->pc);
			else if (!m->last_error[0])
				snprintf(m->last_error, sizeof m->last_error, "crashed at PC=%04x", avr->pc);
			m->crash_cycle = avr->cycle;
			return;
		}
		snprintf(m->last_error, sizeof m->last_error, "%s", clean);
		/* simavr 1.6 logs an invalid opcode and carries on as if it were a
		 * NOP; a real part would run into garbage, so call it a crash. */
		if (strstr(clean, "Invalid Opcode") || strstr(clean, "CRASH")) {
			avr->state = cpu_Crashed;
			m->crash_cycle = avr->cycle;
		}
	}
}

void m162_install_logger(void)
{
	avr_global_logger_set(m162_logger);
}

/* ------------------------------------------------------------------ */
/* run loop */

#define M162_MCUCR MCUCR
#define M162_SE SE
#define M162_WDTCR WDTCR
#define M162_WDE WDE

/* simavr 1.6 makes an instruction that sets I (SEI, RETI, a write to SREG)
 * wait two instructions before a pending interrupt (avr_sreg_set:
 * interrupt_state = -2; avr_service_interrupts counts it up once per step).
 * The datasheet ("Reset and Interrupt Handling") gives one: "the
 * instruction following SEI will be executed before any pending
 * interrupts", and after RETI the part "will always return to the main
 * program and execute one more instruction before any pending interrupt is
 * served".  (simavr fixed this after 1.6: upstream 4963a90, -1.) */
#define M162_OPCODE_SLEEP 0x9588
#define M162_WAKE_HALT 4 /* cycles: "the MCU is halted for four cycles" */
/* "Interrupt Response Time": "The interrupt execution response for all the
 * enabled AVR interrupts is four clock cycles minimum.  After four clock
 * cycles the Program Vector address for the actual interrupt handling
 * routine is executed.  During this four clock cycle period, the Program
 * Counter is pushed onto the Stack."  simavr 1.6 pushes the PC and jumps
 * to the vector in no time; the vector's JMP (3 cycles) and RETI (4) it
 * counts right.  From sleep the response is M162_WAKE_HALT more. */
#define M162_INT_RESPONSE 4

static int m162_is_sleep_at(avr_t *avr, avr_flashaddr_t pc)
{
	return (avr->flash[pc] | (avr->flash[pc + 1] << 8)) == M162_OPCODE_SLEEP;
}

/* After an instruction that left interrupt_state set or the core not
 * running (rare: around interrupts and at SLEEP; kept out of the step's
 * hot path).  Sets m->slept if the core went to sleep in it. */
static __attribute__((noinline)) void m162_after_instruction(avr_t *avr, m162_t *m)
{
	if (avr->interrupt_state == -2)
		avr->interrupt_state = -1; /* one instruction, not two (above) */
	if (avr->state == cpu_Sleeping) {
		if (!(avr->data[M162_MCUCR] & (1 << M162_SE))) {
			avr->state = cpu_Running; /* SLEEP with SE clear is a no-op */
			return;
		}
		m->sleeps++;
		m->slept = 1;
		return;
	}
	/* simavr's SLEEP declines to sleep while an interrupt is pending ("sei;
	 * sleep" with one already raised).  The part "will enter sleep before
	 * any pending interrupt(s)", and that interrupt wakes it at once
	 * (m162_serve).  avr->pc is the instruction avr_run_one ran. */
	if (avr->state == cpu_Running && avr->interrupt_state > 0 && avr->sreg[S_I] &&
			(avr->data[M162_MCUCR] & (1 << M162_SE)) && m162_is_sleep_at(avr, avr->pc)) {
		m->sleeps++;
		m->slept = 1;
	}
}

/* simavr's avr_service_interrupts plus the response time: entering a vector
 * clears I (a masked vector it drops leaves I set), and then takes
 * M162_INT_RESPONSE cycles.  Returns 1 if a vector was entered. */
static int m162_service(avr_t *avr)
{
	int serving = avr->interrupt_state > 0 && avr->sreg[S_I];
	avr_service_interrupts(avr);
	if (!serving || avr->sreg[S_I])
		return 0;
	avr->cycle += M162_INT_RESPONSE;
	return 1;
}

/* Serve a pending interrupt (or count down after SEI).  m->slept: the core
 * was asleep in this step (or its SLEEP was declined): if an interrupt woke
 * it, the part is "halted for four cycles" (plus the start-up time: none in
 * idle mode) on top of the response: 8 cycles before the vector. */
static __attribute__((noinline)) void m162_serve(avr_t *avr, m162_t *m)
{
	int serve = avr->interrupt_state > 0; /* not a count-down after SEI */
	int entered = m162_service(avr);
	if (!m->slept || !serve || avr->state != cpu_Running)
		return;
	/* simavr drops a pending vector that was masked meanwhile: try the
	 * next; if none is served, the part sleeps on */
	while (!entered && avr->sreg[S_I] && avr->interrupt_state > 0)
		entered = m162_service(avr);
	if (entered) {
		avr->cycle += M162_WAKE_HALT;
		m->slept_cycles += M162_WAKE_HALT;
	} else {
		avr->state = cpu_Sleeping;
	}
}

/* RETI: "When the AVR exits from an interrupt, it will always return to the
 * main program and execute one more instruction before any pending
 * interrupt is served" -- also when I was already set (a handler that
 * re-enabled interrupts), where simavr 1.6's avr_sreg_set leaves
 * interrupt_state alone and serves a pending interrupt at once.  simavr
 * raises the table's "running" IRQ in RETI after setting I, and on entry
 * after clearing it: I set here means RETI.  -1: one instruction (the
 * count-down of avr_service_interrupts); an interrupt raised meanwhile
 * leaves it alone (avr_raise_interrupt sets 1 only from 0). */
static void m162_reti(struct avr_irq_t *irq, uint32_t value, void *param)
{
	(void)irq;
	(void)value;
	avr_t *avr = param;
	if (avr->sreg[S_I])
		avr->interrupt_state = -1;
}

/* One instruction (or one sleep step), like simavr's avr_callback_run_raw
 * but in virtual time only.  Only our ATmega162 runs it (its register
 * addresses are hard-coded here); a stock core runs simavr's own step.
 * Runs once per instruction: the rare cases are in the two functions above. */
static void m162_run_step(avr_t *avr)
{
	m162_t *m = m162_of(avr);
	avr_flashaddr_t new_pc = avr->pc;

	if (avr->state == cpu_Running) {
		new_pc = avr_run_one(avr);
		m->slept = 0;
		if (__builtin_expect(avr->interrupt_state || avr->state != cpu_Running, 0))
			m162_after_instruction(avr, m);
		/* The stack ran out of SRAM into the I/O registers.  gcc sets SP
		 * with SPH first, so one or two instructions may see a low SP in
		 * passing; a real overflow stays low. */
		uint16_t sp = avr->data[R_SPL] | (avr->data[R_SPH] << 8);
		if (sp >= RAMSTART - 1)
			m->sp_low_count = 0;
		else if (++m->sp_low_count >= 4 && avr->state != cpu_Crashed) {
			snprintf(m->last_error, sizeof m->last_error,
					"stack overflow: SP=%04x below SRAM at PC=%04x", sp, avr->pc);
			avr->state = cpu_Crashed;
			m->crash_cycle = avr->cycle;
		}
	} else {
		m->slept = avr->state == cpu_Sleeping;
	}
	avr_cycle_count_t sleep = avr_cycle_timer_process(avr);
	avr->pc = new_pc;
	/* a timer (the watchdog) swapped in a reset callback: let it run next,
	 * rather than sleeping on past the moment of the reset */
	if (avr->run != m162_run_step)
		return;

	if (avr->state == cpu_Sleeping) {
		if (!avr->sreg[S_I] && !(avr->data[M162_WDTCR] & (1 << M162_WDE))) {
			/* interrupts off and no watchdog to reset it: simavr calls this
			 * the end of the program */
			avr->state = cpu_Done;
			return;
		}
		/* Never past the quantum's end, where the scheduler delivers the
		 * bytes other MCUs sent meanwhile.  The SLEEP instruction itself
		 * may have ended on (or just past) the boundary: then stay put
		 * and sleep on in the next quantum. */
		avr_cycle_count_t target = avr->cycle + 1 + sleep;
		if (target > m->quantum_end)
			target = m->quantum_end > avr->cycle ? m->quantum_end : avr->cycle;
		m->slept_cycles += target - avr->cycle;
		avr->cycle = target;
	}
	if (avr->interrupt_state && (avr->state == cpu_Running || avr->state == cpu_Sleeping))
		m162_serve(avr, m);
}

const char *m162_state_name(int st)
{
	switch (st) {
	case cpu_Running: return "running";
	case cpu_Sleeping: return "sleeping";
	case cpu_Crashed: return "crashed";
	case cpu_Done: return "done";
	default: return "stopped";
	}
}

static void m162_sleep_virtual(avr_t *avr, avr_cycle_count_t how_long)
{
	(void)avr;
	(void)how_long; /* virtual time: the caller advances avr->cycle */
}

void m162_run_until(m162_t *m, uint64_t cluster_end)
{
	avr_t *avr = m->avr;
	uint64_t end = m162_to_local(m, cluster_end);
	m->quantum_end = end;
	if (m->level_armed)
		m162_extint_level(m);
	while (avr->cycle < end) {
		int st = avr->state;
		if (st != cpu_Running && st != cpu_Sleeping)
			break;
		/* avr->run is normally m162_run_step; the watchdog swaps in its own
		 * reset callback for one call, so go through the pointer. */
		avr->run(avr);
	}
}

/* ------------------------------------------------------------------ */
/* init / reset */

static void m162_ignore_write(avr_t *avr, avr_io_addr_t addr, uint8_t v, void *param)
{
	(void)avr; (void)addr; (void)v; (void)param;
}

/* simavr 1.6 finishes every SPI transfer 100 us after SPDR is written,
 * whatever the clock; on the part it takes 8 SCK periods. */
static void m162_spdr_write(avr_t *avr, avr_io_addr_t addr, uint8_t v, void *param)
{
	m162_t *m = m162_of(avr);
	avr_spi_t *spi = &m->mcu.spi;
	m->spdr_write_orig(avr, addr, v, param);
	static const uint8_t div[8] = { 4, 16, 64, 128, 2, 8, 32, 64 };
	int idx = (avr->data[SPCR] & 3) | ((avr->data[SPSR] & 1) << 2);
	for (avr_cycle_timer_slot_p t = avr->cycle_timers.timer; t; t = t->next) {
		if (t->param == spi) {
			avr_cycle_timer_register(avr, 8u * div[idx], t->timer, spi);
			break;
		}
	}
}

static void m162_pinlog_add(m162_t *m, int idx, uint8_t value)
{
	if (value == m->last_port[idx])
		return;
	m->last_port[idx] = value;
	if (m->ir) /* the IR selector's history: cut bytes (ir_medium.c) */
		ir_note_port(m->ir, idx, value, m162_to_cluster(m, m->avr->cycle));
	if (m->wake_ports & (1u << idx))
		m->woke = 1;
	if (m->pinlog_len >= M162_PINLOG_MAX) {
		m->pinlog_dropped++;
		return;
	}
	if (m->pinlog_len == m->pinlog_cap) {
		size_t cap = m->pinlog_cap ? m->pinlog_cap * 2 : 256;
		m162_pinrec_t *n = realloc(m->pinlog, cap * sizeof *n);
		if (!n) {
			m->pinlog_dropped++;
			return;
		}
		m->pinlog = n;
		m->pinlog_cap = cap;
	}
	m->pinlog[m->pinlog_len++] = (m162_pinrec_t){ m162_to_cluster(m, m->avr->cycle),
		(char)('A' + idx), value };
	m->changed = 1;
}

static void m162_port_change(struct avr_irq_t *irq, uint32_t value, void *param)
{
	struct m162_porthook_t *h = (struct m162_porthook_t *)param;
	(void)irq;
	m162_pinlog_add(h->m, h->idx, (uint8_t)value);
}

/* A reset clears PORTx without a write simavr would signal: log it, so the
 * pin log's reader sees outputs drop (a watchdog reset releases magnets). */
static void m162_log_reset_ports(m162_t *m)
{
	for (int i = 0; i < M162_NPORTS; i++) {
		m162_pinlog_add(m, i, 0);
		/* simavr keeps the PORTx IRQ's last value through the reset and
		 * filters a write of it: the firmware setting the same outputs
		 * again after the reset would go unseen (the IR selector's history
		 * stuck at 0, ir_medium.c) */
		avr_irq_t *irq = m->is_m162 ? avr_io_getirq(m->avr, AVR_IOCTL_IOPORT_GETIRQ('A' + i),
				IOPORT_IRQ_REG_PORT) : NULL;
		if (irq)
			irq->value = 0;
	}
}

/* Level-triggered INT0/INT1 (ISC = 00, the reset default).  simavr polls a
 * low pin every single cycle (with a malloc per poll), whether or not the
 * interrupt is enabled, which stops a sleeping MCU from skipping ahead: a
 * magnet line driven low on PD2/PD3 made idle firmware ~100x slower.  We turn
 * that off and re-request the interrupt while the pin stays low at the
 * moments it can matter: when its handler returns, when GICR is written, and
 * at every quantum boundary. */
static void m162_extint_level(m162_t *m)
{
	avr_t *avr = m->avr;
	for (int i = 0; i < 2; i++) {
		avr_int_vector_t *v = &m->mcu.extint.eint[i].vector;
		if (v->pending || !avr_regbit_get(avr, v->enable))
			continue;
		if (avr_regbit_get_array(avr, m->mcu.extint.eint[i].isc, 2) != 0)
			continue;
		if (!(avr->data[PIND] & (1 << m->mcu.extint.eint[i].port_pin)))
			avr_raise_interrupt(avr, v);
	}
}

static void m162_extint_returned(struct avr_irq_t *irq, uint32_t value, void *param)
{
	(void)irq;
	if (!value)
		m162_extint_level((m162_t *)param);
}

static void m162_gicr_write(avr_t *avr, avr_io_addr_t addr, uint8_t v, void *param)
{
	(void)param;
	avr_core_watch_write(avr, addr, v);
	m162_t *m = m162_of(avr);
	/* the per-quantum level check runs only while INT0 or INT1 is enabled */
	m->level_armed = v & ((1 << INT0) | (1 << INT1));
	m162_extint_level(m);
}

/* ------------------------------------------------------------------ */
/* watchdog: off after every reset; WDRF does not force WDE on this part */

/* Cancel every cycle timer a peripheral (its param) has armed. */
static void m162_cancel_timers_of(avr_t *avr, void *param)
{
	avr_cycle_timer_t fns[MAX_CYCLE_TIMERS];
	int n = 0;
	for (avr_cycle_timer_slot_p t = avr->cycle_timers.timer; t; t = t->next)
		if (t->param == param)
			fns[n++] = t->timer;
	for (int i = 0; i < n; i++)
		avr_cycle_timer_cancel(avr, fns[i], param);
}

static void m162_wdtcr_write(avr_t *avr, avr_io_addr_t addr, uint8_t v, void *param)
{
	m162_t *m = m162_of(avr);
	/* simavr keeps WDE set while WDRF is (ATmega48-style); hide WDRF from it */
	uint8_t wdrf = avr_regbit_get(avr, m->mcu.watchdog.wdrf);
	avr_regbit_clear(avr, m->mcu.watchdog.wdrf);
	m->wdtcr_write_orig(avr, addr, v, param);
	if (wdrf)
		avr_regbit_set(avr, m->mcu.watchdog.wdrf);
}

static void m162_watchdog_reset(m162_t *m)
{
	m->avr->data[WDTCR] = 0;
	m162_cancel_timers_of(m->avr, &m->mcu.watchdog);
}

/* ------------------------------------------------------------------ */
/* timers 0..3: exact TCNT writes and prescaler phase */

/* prescaler_base index of each timer: timers 0, 1 and 3 share a prescaler
 * (PSR310), timer 2 has its own (PSR2). */
#define M162_PRESCALER_T0 0
#define M162_PRESCALER_T2 1

/* simavr has (re)armed timer p as if it counted from 0 now.  Move its
 * overflow and compare timers so that, counting from count, the overflow
 * falls on the right edge of the free-running prescaler. */
static void m162_timer_align(m162_t *m, avr_timer_t *p, int prescaler, uint32_t count)
{
	avr_t *avr = m->avr;
	if (!p->tov_cycles || !p->tov_top || !p->cs_div_value ||
			(p->ext_clock_flags & (AVR_TIMER_EXTCLK_FLAG_TN | AVR_TIMER_EXTCLK_FLAG_AS2)))
		return;
	uint64_t div = p->cs_div_value, now = avr->cycle, base = m->prescaler_base[prescaler];
	uint64_t first_edge = base + ((now - base) / div + 1) * div;
	uint32_t edges = count < p->tov_top ? p->tov_top + 1 - count : 1;
	uint64_t overflow = first_edge + (edges - 1) * div;
	uint64_t want_base = overflow - p->tov_cycles;
	int64_t shift = (int64_t)(want_base - p->tov_base);
	if (!shift)
		return;
	p->tov_base = want_base;
	struct { avr_cycle_timer_t fn; uint64_t when; } armed[8];
	int n = 0;
	for (avr_cycle_timer_slot_p t = avr->cycle_timers.timer; t && n < 8; t = t->next)
		if (t->param == p)
			armed[n++] = (typeof(armed[0])){ t->timer, t->when };
	for (int i = 0; i < n; i++) {
		uint64_t when = armed[i].when + shift;
		if (when > now)
			avr_cycle_timer_register(avr, when - now, armed[i].fn, p);
		else
			avr_cycle_timer_cancel(avr, armed[i].fn, p); /* already passed this period */
	}
}

static avr_timer_t *m162_timer(m162_t *m, int n)
{
	avr_timer_t *timers[4] = { &m->mcu.timer0, &m->mcu.timer1, &m->mcu.timer2,
		&m->mcu.timer3 };
	return timers[n];
}

/* which of the four timers p is (the index of its saved write handlers) */
static int m162_timer_number(m162_t *m, avr_timer_t *p)
{
	for (int n = 0; n < 3; n++)
		if (p == m162_timer(m, n))
			return n;
	return 3;
}

static int m162_prescaler_of(m162_t *m, avr_timer_t *p)
{
	return p == &m->mcu.timer2 ? M162_PRESCALER_T2 : M162_PRESCALER_T0;
}

/* The count the timer holds, both bytes of a 16-bit one: a stopped timer
 * keeps what TCNT was set to; a running one is read as the firmware reads
 * it (simavr's read refreshes TCNTnH too). */
static uint32_t m162_timer_count(avr_t *avr, avr_timer_t *p)
{
	if (p->tov_cycles) {
		avr_io_addr_t io = AVR_DATA_TO_IO(p->r_tcnt);
		avr->io[io].r.c(avr, p->r_tcnt, avr->io[io].r.param);
	}
	return avr->data[p->r_tcnt] | (p->r_tcnth ? (uint32_t)avr->data[p->r_tcnth] << 8 : 0);
}

/* A TCNT write (the low byte of a 16-bit one: avr-gcc writes the high
 * byte first, which simavr keeps in TCNTnH) */
static void m162_tcnt_write(avr_t *avr, avr_io_addr_t addr, uint8_t v, void *param)
{
	m162_t *m = m162_of(avr);
	avr_timer_t *p = param;
	m->tcnt_write_orig[m162_timer_number(m, p)](avr, addr, v, param);
	uint32_t count = v | (p->r_tcnth ? (uint32_t)avr->data[p->r_tcnth] << 8 : 0);
	m162_timer_align(m, p, m162_prescaler_of(m, p), count);
}

static void m162_tccr_write(avr_t *avr, avr_io_addr_t addr, uint8_t v, void *param)
{
	m162_t *m = m162_of(avr);
	avr_timer_t *p = param;
	uint64_t was_cycles = p->tov_cycles, was_div = p->cs_div_value;
	uint32_t count = m162_timer_count(avr, p);
	m->tccr_write_orig[m162_timer_number(m, p)](avr, addr, v, param);
	if (p->tov_cycles != was_cycles || p->cs_div_value != was_div)
		m162_timer_align(m, p, m162_prescaler_of(m, p), count);
}

/* A prescaler restarted: every running timer on it goes on with the count
 * it holds from the next edge of the restarted prescaler; a stopped one
 * counts from this base when it starts. */
static void m162_prescaler_restarted(m162_t *m, int prescaler)
{
	avr_t *avr = m->avr;
	m->prescaler_base[prescaler] = avr->cycle;
	for (int n = 0; n < 4; n++) {
		avr_timer_t *p = m162_timer(m, n);
		if (m162_prescaler_of(m, p) == prescaler && p->tov_cycles)
			m162_timer_align(m, p, prescaler, m162_timer_count(avr, p));
	}
}

/* SFIOR: PSR2 and PSR310 restart a prescaler; the bits read back 0 */
static void m162_sfior_write(avr_t *avr, avr_io_addr_t addr, uint8_t v, void *param)
{
	(void)param;
	m162_t *m = m162_of(avr);
	if (v & (1 << PSR310))
		m162_prescaler_restarted(m, M162_PRESCALER_T0);
	if (v & (1 << PSR2))
		m162_prescaler_restarted(m, M162_PRESCALER_T2);
	avr_core_watch_write(avr, addr, v & ~((1 << PSR310) | (1 << PSR2)));
}

/* A reset does not unplug what drives the pins from outside (DIP switches):
 * put the external levels back into PINx, since simavr's IRQs filter a
 * later set_input of the same value as "no change". The other pins read 0
 * after the reset, and their IRQs must say so too: else the firmware's
 * pull-up (PORTx bit set, DDRx clear) raises an IRQ that already holds 1,
 * simavr drops it as no change, and the pin reads 0 for good (after a
 * watchdog reset the RF12 board read its mode jumper as closed). */
static void m162_reapply_external(m162_t *m)
{
	avr_ioport_t *ports[M162_NPORTS] = { &m->mcu.porta, &m->mcu.portb, &m->mcu.portc,
		&m->mcu.portd, &m->mcu.porte };
	for (int i = 0; i < M162_NPORTS; i++) {
		uint8_t mask = ports[i]->external.pull_mask;
		uint8_t *pin = &m->avr->data[m162_port_regs[i][0]];
		*pin = (uint8_t)((*pin & ~mask) | (ports[i]->external.pull_value & mask));
		for (int b = 0; b < 8; b++)
			if (!(mask & (1 << b)))
				ports[i]->io.irq[b].value = 0;
		ports[i]->io.irq[IOPORT_IRQ_PIN_ALL].value = *pin;
	}
}

void m162_drive_input(m162_t *m, int port, uint8_t mask, uint8_t value)
{
	avr_ioport_t *ports[M162_NPORTS] = { &m->mcu.porta, &m->mcu.portb, &m->mcu.portc,
		&m->mcu.portd, &m->mcu.porte };
	avr_ioport_t *io = ports[port];
	/* An external driver wins over the internal pull-up: simavr's "external"
	 * state is re-applied whenever PORTx/DDRx change. */
	io->external.pull_mask |= mask;
	io->external.pull_value = (io->external.pull_value & ~mask) | (value & mask);
	for (int b = 0; b < 8; b++)
		if (mask & (1 << b))
			avr_raise_irq(io->io.irq + b, (value >> b) & 1);
}

/* A reset stops the USARTs mid-byte: the IR medium cuts the byte on the air
 * there, and Python's medium learns of it through resets(). */
static void m162_note_reset(m162_t *m)
{
	uint64_t now = m162_to_cluster(m, m->avr->cycle);
	if (m->ir)
		ir_note_reset(m->ir, now);
	if (m->n_resets == 64) { /* nobody takes them: keep the latest */
		memmove(m->resets, m->resets + 1, 63 * sizeof *m->resets);
		m->n_resets--;
	}
	if (GROW(m->resets, m->n_resets, m->cap_resets, 4) == 0)
		m->resets[m->n_resets++] = now;
	m->changed = 1;
}

static void m162_fixup_reset(avr_io_t *io)
{
	m162_t *m = (m162_t *)((char *)io - offsetof(m162_t, fixup_io));
	for (int i = 0; i < 2; i++) {
		avr_extint_set_strict_lvl_trig(m->avr, i, 0);
		avr_irq_register_notify(m->mcu.extint.eint[i].vector.irq + AVR_INT_IRQ_RUNNING,
				m162_extint_returned, m);
	}
	m->level_armed = 0;
	m->prescaler_base[M162_PRESCALER_T0] = m->prescaler_base[M162_PRESCALER_T2] =
		m->avr->cycle;
	m162_watchdog_reset(m);
	m162_note_reset(m);
	m162_log_reset_ports(m);
	m162_usart_reset(m);
	m162_reapply_external(m);
}

static void m162_stock_reset(avr_io_t *io)
{
	m162_log_reset_ports((m162_t *)((char *)io - offsetof(m162_t, fixup_io)));
}

static const avr_io_t m162_fixup_io_template = {
	.kind = "m162-fixup",
	.reset = m162_fixup_reset,
};

static void m162_init(avr_t *avr)
{
	struct mcu_t *mcu = (struct mcu_t *)avr;
	m162_t *m = m162_of(avr);

	/* registered first => reset last (simavr resets in reverse order) */
	m->fixup_io = m162_fixup_io_template;
	avr_register_io(avr, &m->fixup_io);

	avr_eeprom_init(avr, &mcu->eeprom);
	avr_flash_init(avr, &mcu->selfprog);
	avr_watchdog_init(avr, &mcu->watchdog);
	avr_ioport_init(avr, &mcu->porta);
	avr_ioport_init(avr, &mcu->portb);
	avr_ioport_init(avr, &mcu->portc);
	avr_ioport_init(avr, &mcu->portd);
	avr_ioport_init(avr, &mcu->porte);
	avr_extint_init(avr, &mcu->extint);
	avr_uart_init(avr, &mcu->uart0);
	avr_uart_init(avr, &mcu->uart1);
	avr_timer_init(avr, &mcu->timer0);
	avr_timer_init(avr, &mcu->timer1);
	avr_timer_init(avr, &mcu->timer2);
	avr_timer_init(avr, &mcu->timer3);
	avr_spi_init(avr, &mcu->spi);

	avr_register_io_write(avr, GICR, m162_gicr_write, NULL);
	avr_register_io_write(avr, SFIOR, m162_sfior_write, NULL);

	m->wdtcr_write_orig = avr->io[AVR_DATA_TO_IO(WDTCR)].w.c;
	avr->io[AVR_DATA_TO_IO(WDTCR)].w.c = m162_wdtcr_write;
	for (int n = 0; n < 4; n++) {
		avr_timer_t *p = m162_timer(m, n);
		avr_io_addr_t tcnt = AVR_DATA_TO_IO(p->r_tcnt);
		avr_io_addr_t tccr = AVR_DATA_TO_IO(p->cs[0].reg); /* TCCRn, TCCR1B, TCCR3B */
		m->tcnt_write_orig[n] = avr->io[tcnt].w.c;
		avr->io[tcnt].w.c = m162_tcnt_write;
		m->tccr_write_orig[n] = avr->io[tccr].w.c;
		avr->io[tccr].w.c = m162_tccr_write;
	}

	m->spdr_write_orig = avr->io[AVR_DATA_TO_IO(SPDR)].w.c;
	avr->io[AVR_DATA_TO_IO(SPDR)].w.c = m162_spdr_write;

	/* PINx is read-only on this part */
	for (int i = 0; i < M162_NPORTS; i++) {
		avr_io_addr_t a = AVR_DATA_TO_IO(m162_port_regs[i][0]);
		avr->io[a].w.c = m162_ignore_write;
		avr->io[a].w.param = NULL;
	}

	m->usart[0].u = &mcu->uart0;
	m->usart[0].shared_addr = UCSR0C;
	m->usart[0].ubrrh_addr = M162_UBRR0H_SHADOW;
	m->usart[0].ucsrc_addr = M162_UCSR0C_SHADOW;
	m->usart[1].u = &mcu->uart1;
	m->usart[1].shared_addr = UCSR1C;
	m->usart[1].ubrrh_addr = M162_UBRR1H_SHADOW;
	m->usart[1].ucsrc_addr = M162_UCSR1C_SHADOW;
	m162_usart_init(m);
}

static void m162_core_reset(avr_t *avr)
{
	(void)avr; /* peripheral fix-ups run in m162_fixup_reset, after the modules */
}

static void m162_hook_ports(m162_t *m)
{
	for (int i = 0; i < M162_NPORTS; i++) {
		avr_irq_t *irq = avr_io_getirq(m->avr, AVR_IOCTL_IOPORT_GETIRQ('A' + i),
				IOPORT_IRQ_REG_PORT);
		m->porthook[i].m = m;
		m->porthook[i].idx = i;
		if (irq)
			avr_irq_register_notify(irq, m162_port_change, &m->porthook[i]);
	}
}

static void m162_setup_run(m162_t *m)
{
	m->avr->run = m162_run_step;
	m->avr->sleep = m162_sleep_virtual;
	m->avr->log = LOG_NONE;
	m->avr->gdb_port = 0;
}

static void m162_widen_data(avr_t *avr);

m162_t *m162_make(void)
{
	m162_t *m = calloc(1, sizeof *m);
	if (!m)
		return NULL;
	memcpy(&m->mcu, &mcu_mega162, sizeof mcu_mega162);
	m->is_m162 = 1;
	m->avr = &m->mcu.core;
	m->avr->custom.data = m;
	for (int i = 0; i < M162_NUARTS; i++) {
		m->usart[i].mcu = m;
		m->usart[i].index = i;
		m->usart[i].ir_sel_port = -1;
	}
	avr_init(m->avr); /* calls m162_init, then resets */
	m162_widen_data(m->avr);
	m162_setup_run(m);
	m162_hook_ports(m);
	avr_irq_register_notify(m->avr->interrupts.irq + AVR_INT_IRQ_RUNNING, m162_reti, m->avr);
	return m;
}

/* A stock simavr core in the same wrapper, for comparison runs (traces in
 * tests/hil_sim/test_core_peripherals.py).  Only the scheduler's quanta,
 * logger and pin log apply; the USART log uses the output IRQ. */
static void m162_stock_uart_out(struct avr_irq_t *irq, uint32_t value, void *param)
{
	m162_usart_t *s = (m162_usart_t *)param;
	(void)irq;
	uint64_t now = m162_to_cluster(s->mcu, s->mcu->avr->cycle);
	m162_usart_log(s, (m162_txrec_t){ now, now, now, (uint8_t)value, 0, 0 });
}

m162_t *m162_make_stock(const char *mmcu)
{
	avr_t *stock = avr_make_mcu_by_name(mmcu);
	if (!stock)
		return NULL;
	m162_t *m = calloc(1, sizeof *m);
	if (!m) {
		free(stock);
		return NULL;
	}
	m->avr = stock;
	m->is_m162 = 0;
	stock->custom.data = m;
	for (int i = 0; i < M162_NUARTS; i++) {
		m->usart[i].mcu = m;
		m->usart[i].index = i;
		m->usart[i].ir_sel_port = -1;
	}
	avr_init(stock);
	m162_widen_data(stock);
	m->fixup_io = (avr_io_t){ .kind = "pinlog-reset", .reset = m162_stock_reset };
	avr_register_io(stock, &m->fixup_io);
	m162_setup_run(m);
	/* simavr's own step function: the comparison is with the stock loop,
	 * and ours stays free of tests for which core it is running */
	stock->run = avr_callback_run_raw;
	m162_hook_ports(m);
	for (int i = 0; i < M162_NUARTS; i++) {
		uint32_t flags = 0;
		avr_ioctl(stock, AVR_IOCTL_UART_SET_FLAGS('0' + i), &flags);
		avr_irq_t *irq = avr_io_getirq(stock, AVR_IOCTL_UART_GETIRQ('0' + i), UART_IRQ_OUTPUT);
		if (irq)
			avr_irq_register_notify(irq, m162_stock_uart_out, &m->usart[i]);
	}
	return m;
}

/* avr_terminate frees the peripherals' IRQs but not those embedded in the
 * interrupt vectors (their names and notify hooks) nor the IRQ pool itself:
 * ~4.7 KB per MCU in simavr 1.6.  Whatever is still in the pool after
 * avr_terminate is one of those. */
static void m162_free_irq_pool(avr_t *avr)
{
	avr_irq_pool_t *pool = &avr->irq_pool;
	for (int i = 0; i < pool->count; i++) {
		avr_irq_t *irq = pool->irq[i];
		if (!irq)
			continue;
		/* embedded in a vector: free its name and hooks, not the IRQ */
		irq->flags &= ~IRQ_FLAG_ALLOC;
		avr_free_irq(irq, 1);
	}
	free(pool->irq);
	pool->irq = NULL;
	pool->count = 0;
}

void m162_free(m162_t *m)
{
	if (!m)
		return;
	avr_t *avr = m->avr;
	avr_terminate(avr);
	m162_free_irq_pool(avr);
	for (int i = 0; i < M162_NUARTS; i++) {
		free(m->usart[i].log);
		free(m->usart[i].rx_log);
	}
	free(m->pinlog);
	free(m->resets);
	if (!m->is_m162)
		free(avr);
	free(m);
}

/* The device an avr-gcc ELF was built for: the last string of its
 * .note.gnu.avr.deviceinfo note (avr-gcc 5 and later write one); an empty
 * string when it has none. */
static void elf_device(const char *path, char *dev, size_t devlen)
{
	dev[0] = 0;
	int fd = open(path, O_RDONLY);
	if (fd < 0)
		return;
	elf_version(EV_CURRENT);
	Elf *e = elf_begin(fd, ELF_C_READ, NULL);
	size_t shstrndx;
	if (e && elf_getshdrstrndx(e, &shstrndx) == 0) {
		for (Elf_Scn *scn = NULL; (scn = elf_nextscn(e, scn)) != NULL;) {
			GElf_Shdr sh;
			const char *name;
			if (!gelf_getshdr(scn, &sh) || !(name = elf_strptr(e, shstrndx, sh.sh_name)) ||
					strcmp(name, ".note.gnu.avr.deviceinfo") != 0)
				continue;
			Elf_Data *d = elf_getdata(scn, NULL);
			if (!d || !d->d_buf)
				break;
			const char *p = d->d_buf;
			size_t end = d->d_size;
			while (end && !p[end - 1])
				end--;
			size_t start = end;
			while (start && p[start - 1])
				start--;
			snprintf(dev, devlen, "%.*s", (int)(end - start), p + start);
			break;
		}
	}
	if (e)
		elf_end(e);
	close(fd);
}

/* simavr sizes data memory to RAMEND + 1 and, after it logs a write beyond
 * it as invalid, still stores the byte: a firmware that runs off its stack
 * or an array would write into the simulator's own heap (and other MCUs'
 * state). 64 KiB covers every address an AVR instruction can form. */
static void m162_widen_data(avr_t *avr)
{
	uint8_t *data = calloc(1, 0x10000);
	if (!data)
		return; /* keep simavr's: no worse than before */
	memcpy(data, avr->data, avr->ramend + 1u);
	free(avr->data);
	avr->data = data;
}

/* libelf accepts some files that are not ELF at all: check the header. */
static int check_avr_elf(const char *path, char *err, size_t errlen)
{
	unsigned char h[20];
	FILE *f = fopen(path, "rb");
	if (!f) {
		snprintf(err, errlen, "%s: cannot open", path);
		return -1;
	}
	size_t n = fread(h, 1, sizeof h, f);
	fclose(f);
	if (n < sizeof h || memcmp(h, "\x7f" "ELF", 4) != 0) {
		snprintf(err, errlen, "%s: not an ELF file", path);
		return -1;
	}
	if (h[4] != 1 || h[5] != 1 || (h[18] | (h[19] << 8)) != 83 /* EM_AVR */) {
		snprintf(err, errlen, "%s: ELF file, but not for the AVR", path);
		return -1;
	}
	return 0;
}

int m162_load_elf(m162_t *m, const char *path, char *err, size_t errlen)
{
	if (check_avr_elf(path, err, errlen) != 0)
		return -1;
	char dev[32];
	elf_device(path, dev, sizeof dev);
	if (m->is_m162 && dev[0] && strcmp(dev, "atmega162") != 0) {
		/* its registers, RAM and vectors are elsewhere: it would run astray */
		snprintf(err, errlen, "%s: built for the %s, not the ATmega162", path, dev);
		return -1;
	}
	/* elf_firmware_t is big and its layout depends on simavr's build flags:
	 * give the library generous room. */
	union {
		elf_firmware_t f;
		char pad[sizeof(elf_firmware_t) + 4096];
	} *fw = calloc(1, sizeof *fw);
	if (!fw) {
		snprintf(err, errlen, "out of memory");
		return -1;
	}
	if (elf_read_firmware(path, &fw->f) != 0) {
		snprintf(err, errlen, "%s: cannot read as an AVR ELF file", path);
		free(fw);
		return -1;
	}
	if (fw->f.flashsize + fw->f.flashbase > m->avr->flashend + 1) {
		snprintf(err, errlen, "%s: program is %u bytes, flash holds %u", path,
				fw->f.flashsize + fw->f.flashbase, m->avr->flashend + 1);
		free(fw->f.flash);
		free(fw);
		return -1;
	}
	avr_load_firmware(m->avr, &fw->f);
	/* the ELF's fuse section may be shorter than 3 bytes; nothing else to do */
	free(fw->f.flash);
	free(fw->f.eeprom);
	free(fw->f.fuse);
	free(fw->f.lockbits);
#if ELF_SYMBOLS && !CONFIG_SIMAVR_TRACE
	/* the symbol table is only kept by tracing builds of simavr */
	for (uint32_t i = 0; i < fw->f.symbolcount; i++)
		free(fw->f.symbol[i]);
	free(fw->f.symbol);
#endif
	free(fw);
	/* avr_load_firmware may install a VCD trace if the ELF asks; we never
	 * want files written behind the caller's back. */
	if (m->avr->vcd) {
		avr_vcd_close(m->avr->vcd);
		free(m->avr->vcd);
		m->avr->vcd = NULL;
	}
	return 0;
}

void m162_reset(m162_t *m)
{
	m->last_error[0] = 0;
	avr_reset(m->avr);
	if (m->is_m162)
		avr_regbit_set(m->avr, m->avr->reset_flags.extrf);
}
