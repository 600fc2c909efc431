/*
 * m162.h -- ATmega162 core for libsimavr 1.6, plus the per-MCU state our
 * lock-step scheduler needs (USART transmit log, receive queue, pin log).
 *
 * simavr ships no ATmega162.  m162_core.c declares one the way simavr's own
 * cores do (one struct of peripheral descriptors); m162_usart.c replaces the
 * parts of simavr's USART that are wrong for us (URSEL register sharing,
 * byte pacing, receive timing, stdout echo, real-time polling sleeps).
 */
#ifndef HEXBOT_M162_H
#define HEXBOT_M162_H

#include <stdint.h>

#include "sim_avr.h"
#include "avr_eeprom.h"
#include "avr_extint.h"
#include "avr_flash.h"
#include "avr_ioport.h"
#include "avr_spi.h"
#include "avr_timer.h"
#include "avr_uart.h"
#include "avr_watchdog.h"

#define M162_NPORTS 5  /* A..E */
#define M162_NUARTS 2

/* One byte as it went over a wire: first edge of the start bit, the middle
 * of its (first) stop bit, where a receiver samples it and raises RXC, and
 * the end of the last stop bit.  All in cluster cycles (nominal clock, see
 * m162_clock_t), so bytes of MCUs on different clocks compare directly. */
typedef struct m162_txrec_t {
	uint64_t start, mid_stop, end;
	uint8_t byte;
	uint8_t format;      /* data bits | parity mode << 4 | stop bits << 6 */
	double bit;          /* sender's bit time in cluster cycles, not rounded (m162_bit_time) */
} m162_txrec_t;

/* A byte waiting to reach a receiver at a given cycle (wire delivery, in the
 * receiver's own cycles), with what a receiver that came on within it needs
 * to read its line (m162_usart_queue_rx). */
typedef struct m162_rxpend_t {
	uint64_t due;
	uint16_t value;   /* byte | UART_INPUT_FE, as read by a receiver on all along */
	uint64_t start;   /* the sender's start bit, cluster cycles */
	double bit;       /* the sender's bit time, cluster cycles */
	uint8_t byte, format; /* as sent (m162_txrec_t) */
	uint8_t frame_ok; /* the receiver's settings took it (m162_usart_frame_ok) */
} m162_rxpend_t;

#define M162_RXQ_SIZE 64

/* A USART receiver came on (RXEN set) or went off (RXEN cleared, or the
 * MCU's reset), at a cluster cycle. */
typedef struct m162_rxmark_t {
	uint64_t cycle;
	int on;
} m162_rxmark_t;

typedef struct m162_usart_t {
	struct m162_t *mcu;
	avr_uart_t *u;
	int index;
	/* UBRRnH and UCSRnC share one I/O address; URSEL picks the target.  The
	 * two registers live at reserved data addresses (see m162_core.c) so that
	 * simavr's regbits keep working on them. */
	uint16_t shared_addr, ubrrh_addr, ucsrc_addr;
	uint64_t last_shared_read; /* cycle+1 of the last read, for the 2-read rule */
	uint32_t frame_cycles;     /* 1 start + data + parity + stop bits */
	uint32_t bit_cycles;
	uint8_t format;            /* as in m162_txrec_t */
	/* transmitter: UDR buffer + shift register */
	int shifting;
	uint64_t shift_start, shift_end;
	uint8_t shift_byte;
	int udr_full;
	uint8_t udr_byte;
	/* log of transmitted bytes (kept only if watched or wired) */
	int keep_log;
	m162_txrec_t *log;
	size_t log_len, log_cap;
	size_t wire_pos;     /* next record to hand to the wire peer */
	size_t take_pos;     /* next record for uart_take() */
	size_t notified_pos; /* records up to here already ended a run() early */
	int watched;
	struct m162_usart_t *peer; /* connect_uart() wire, or NULL */
	/* IR medium routed in C (ir_medium.c): the selector's port (-1: not on
	 * the medium), the next record to route */
	int ir_sel_port;
	size_t ir_pos;
	/* receiver side: bytes in flight on a wire, delivered at their due cycle */
	m162_rxpend_t rxq[M162_RXQ_SIZE];
	unsigned rxq_head, rxq_len;
	uint64_t rx_dropped;
	/* the receiver's on/off changes, until taken (pyavr uart_rx_log; the
	 * last 64 at most, rx_log_lost counts the older ones it lost), and its
	 * state as last noted, on since rx_since (cluster cycles) */
	int rx_on;
	uint64_t rx_since;
	m162_rxmark_t *rx_log;
	size_t rx_log_len, rx_log_cap;
	uint64_t rx_log_lost;
	avr_io_read_t orig_ucsra_read;
	void *orig_ucsra_read_param;
	avr_io_write_t orig_ucsrb_write;
	void *orig_ucsrb_write_param;
	avr_io_write_t orig_ubrrl_write;
	void *orig_ubrrl_write_param;
} m162_usart_t;

typedef struct m162_pinrec_t {
	uint64_t cycle;
	char port;
	uint8_t value;
} m162_pinrec_t;

#define M162_PINLOG_MAX 65536

/* The peripherals of an ATmega162, as simavr descriptors. */
struct mcu_t {
	avr_t core;
	avr_eeprom_t eeprom;
	avr_flash_t selfprog;
	avr_watchdog_t watchdog;
	avr_extint_t extint;
	avr_ioport_t porta, portb, portc, portd, porte;
	avr_uart_t uart0, uart1;
	avr_timer_t timer0, timer1, timer2, timer3;
	avr_spi_t spi;
};

/* Each MCU has its own clock (the boards run on internal RC oscillators,
 * several per cent apart).  The cluster keeps time in cycles of the nominal
 * clock; an MCU's own cycle counter runs at hz/nominal_hz of that rate,
 * anchored at the moment its clock was last set. */
typedef struct m162_clock_t {
	uint32_t hz, nominal_hz;
	uint64_t base_local, base_cluster;
} m162_clock_t;

typedef struct m162_t {
	struct mcu_t mcu; /* our core (unused when running a stock simavr core) */
	m162_clock_t clock;
	int changed;        /* new pin-log records or finished watched bytes since the last look */
	uint64_t prescaler_base[2]; /* cycle the prescalers of timers 0/1/3 and 2 restarted */
	uint8_t level_armed; /* INT0/INT1 enabled with low-level sense (bit per INT) */
	avr_io_t fixup_io;  /* reset hook that runs after every simavr module */
	int is_m162;        /* 0 for a stock simavr core (comparison runs) */
	avr_t *avr;
	char name[64];
	uint64_t quantum_end; /* a sleeping core never skips past this cycle */
	/* Firmware cost counters (own cycles): cycles skipped asleep (with the
	 * four-cycle halt of each wake-up) and SLEEP instructions executed with
	 * SE set; awake cycles = cycle - slept_cycles.  A few adds per sleep,
	 * nothing per instruction; never reset. */
	uint64_t slept_cycles, sleeps;
	m162_usart_t usart[M162_NUARTS];
	/* pin log: PORTx output values, one record per change */
	uint8_t last_port[M162_NPORTS];
	m162_pinrec_t *pinlog;
	size_t pinlog_len, pinlog_cap;
	uint64_t pinlog_dropped;
	struct m162_porthook_t { struct m162_t *m; int idx; } porthook[M162_NPORTS];
	struct rf12_t *rf12; /* an RF12 radio on its pins (rf12_part.c), or NULL */
	struct ir_port_t *ir; /* its IR transceiver in the C medium (ir_medium.c), or NULL */
	uint64_t *resets;     /* cluster cycles of its resets, until taken (pyavr resets()) */
	size_t n_resets, cap_resets;
	uint8_t wake_ports;  /* ports (bit per A..E) whose changes end a run() early */
	int woke;            /* such a change happened since the last boundary */
	char last_error[256];
	uint64_t crash_cycle;
	unsigned sp_low_count; /* instructions in a row with SP below SRAM */
	uint8_t slept;      /* asleep in this step: an interrupt now wakes it (m162_serve) */
	avr_io_write_t spdr_write_orig;
	avr_io_write_t wdtcr_write_orig;
	avr_io_write_t tcnt_write_orig[4], tccr_write_orig[4]; /* timers 0..3 */
} m162_t;

/* Core */
m162_t *m162_make(void);                 /* allocates and avr_init()s an ATmega162 */
m162_t *m162_make_stock(const char *mmcu); /* simavr's own core, for comparisons */
void m162_free(m162_t *m);
int m162_load_elf(m162_t *m, const char *path, char *err, size_t errlen);
void m162_install_logger(void);
void m162_run_until(m162_t *m, uint64_t end);
void m162_reset(m162_t *m);
/* Cluster cycles <-> this MCU's own cycles (equal on the nominal clock). */
uint64_t m162_to_local(const m162_t *m, uint64_t cluster_cycle);
uint64_t m162_to_cluster(const m162_t *m, uint64_t local_cycle);
/* A span of the MCU's own cycles (a bit time) in cluster cycles, not
 * rounded: on a clock off nominal it is not a whole number.  One division
 * of exact integers, local * nominal / hz, so Python's twin
 * (simulator.frame_of) computes the same double (docs/simulator.md,
 * "Bit times off nominal"). */
double m162_bit_time(const m162_t *m, uint32_t local_cycles);
/* Change the MCU's clock at cluster cycle now (hz > 0). */
void m162_set_clock(m162_t *m, uint32_t hz, uint64_t now);
/* Drive external levels on the pins of port (0..4 = A..E) in mask: they
 * win over the internal pull-ups, as a part's outputs do. */
void m162_drive_input(m162_t *m, int port, uint8_t mask, uint8_t value);
const char *m162_state_name(int state); /* "running", "sleeping", "crashed", "done", "stopped" */
static inline m162_t *m162_of(avr_t *avr) { return (m162_t *)avr->custom.data; }

/* The IR medium's view of the MCU (ir_medium.c): a port changed, the MCU
 * reset; called from the MCU's own run. */
struct ir_port_t;
void ir_note_port(struct ir_port_t *p, int port, uint8_t value, uint64_t cycle);
void ir_note_reset(struct ir_port_t *p, uint64_t cycle);
/* USART s's receiver came on or went off (m162_usart.c): the medium's
 * receiver, if s is its USART, reads from there (ir_medium.h). */
void ir_note_rx(struct ir_port_t *p, const struct m162_usart_t *s, uint64_t cycle, int on);

/* USART (m162_usart.c) */
void m162_usart_init(m162_t *m);
void m162_usart_reset(m162_t *m);
int m162_usart_put(m162_usart_t *s, uint16_t value); /* 1 = accepted, 0 = dropped */
/* A wire byte r for receiver s, read as value by a receiver on all along
 * (frame_ok: within its tolerance), due at r's mid-stop. */
void m162_usart_queue_rx(m162_usart_t *s, const m162_txrec_t *r, uint16_t value, int frame_ok);
void m162_usart_config(m162_usart_t *s, double *baud, int *data_bits, char *parity,
		int *stop_bits, int *rxen, int *txen);
void m162_usart_set_keep_log(m162_usart_t *s, int keep);
void m162_usart_log(m162_usart_t *s, m162_txrec_t rec); /* append, if the log is kept */
void m162_usart_compact_log(m162_usart_t *s);
/* Would s receive this frame intact?  Same data bits and parity, bit times
 * within tolerance (a fraction: protocol/timing.py BAUD_TOLERANCE). */
int m162_usart_frame_ok(const m162_usart_t *s, const m162_txrec_t *r, double tolerance);
int m162_usart_resample(const m162_usart_t *s, const m162_txrec_t *r); /* -1: no byte */

/* Register addresses (data space) used outside the descriptor table. */
extern const uint16_t m162_port_regs[M162_NPORTS][3]; /* PIN, DDR, PORT */

#endif
