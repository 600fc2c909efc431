/*
 * m162_usart.c -- the ATmega162 USARTs on top of simavr's avr_uart_t.
 *
 * simavr 1.6's UART model is kept for its register bookkeeping (UCSRnA/B
 * write masks, TXC write-one-to-clear, FE status, the receive FIFO), but four
 * things are replaced because they are wrong for a deterministic HIL run:
 *
 *  1. URSEL: UBRRnH and UCSRnC share one I/O address.  A write with bit 7
 *     set goes to UCSRnC, otherwise to UBRRnH.  A read returns UBRRnH, or
 *     UCSRnC when the same location was read in the previous cycle (the
 *     datasheet's two-read sequence).
 *  2. Pacing: simavr counts a parity bit whether or not parity is on (11 bit
 *     times for 8N1).  Here a frame is 1 start + data + parity + stop bits.
 *  3. Transmitter: UDR plus a shift register, as on the part.  A write to an
 *     idle transmitter moves straight to the shift register (UDRE stays set);
 *     a second write waits in UDR (UDRE clear) and starts the moment the
 *     first stop bit ends.  TXC rises when the shifter empties with UDR empty.
 *     Every frame is logged as (start, end, byte).
 *  4. Receiver: a byte handed to m162_usart_put() is complete "now": RXC
 *     rises at once (simavr would wait another frame).  RXEN off drops it;
 *     a full buffer (2-byte FIFO + shift register) drops it and sets DOR.
 *     Every change of the receiver's state (RXEN set or cleared, a reset)
 *     is logged: the IR medium and the wires read a byte the receiver was
 *     off for part of from where it came on (ir_medium.h, wire_put).
 *
 * simavr's stdout echo and real-time sleep on polling are switched off.
 */
#include <stdlib.h>
#include <string.h>

#include "grow.h"
#include "m162.h"
#include "uart_line.h"

#define IO(a) AVR_DATA_TO_IO(a)
#define URSEL 0x80
#define RX_CAPACITY 3

DEFINE_FIFO(uint16_t, uart_fifo);

static int udrie(avr_t *avr, avr_uart_t *u) { return avr_regbit_get(avr, u->udrc.enable); }

static void clear_flag(avr_t *avr, avr_int_vector_t *v)
{
	/* drop a pending request and the flag, even for "sticky" vectors */
	if (v->pending)
		avr_clear_interrupt(avr, v);
	avr_regbit_clear(avr, v->raised);
}

static void recompute_frame(m162_usart_t *s)
{
	avr_t *avr = s->mcu->avr;
	avr_uart_t *u = s->u;
	static const int databits[8] = { 5, 6, 7, 8, 8, 8, 8, 9 };
	uint32_t ubrr = avr->data[u->ubrrl.reg] | ((avr->data[s->ubrrh_addr] & 0x0F) << 8);
	int db = databits[avr_regbit_get(avr, u->ucsz) | (avr_regbit_get(avr, u->ucsz2) << 2)];
	int upm = (avr->data[s->ucsrc_addr] >> 4) & 3;
	int parity = upm >= 2 ? 1 : 0;
	int sb = 1 + avr_regbit_get(avr, u->usbs);
	uint32_t cycles_per_bit = (ubrr + 1) * (avr_regbit_get(avr, u->u2x) ? 8 : 16);
	s->frame_cycles = cycles_per_bit * (1 + db + parity + sb);
	s->bit_cycles = cycles_per_bit;
	s->format = (uint8_t)(db | (upm << 4) | (sb << 6));
	u->cycles_per_byte = s->frame_cycles;
}

/* ---------------------------------------------------------------- */
/* transmitter */

void m162_usart_log(m162_usart_t *s, m162_txrec_t rec)
{
	if (!s->keep_log)
		return;
	if (GROW(s->log, s->log_len, s->log_cap, 64) < 0)
		return;
	s->log[s->log_len++] = rec;
}

static void start_frame(m162_usart_t *s, uint8_t byte, uint64_t when)
{
	m162_t *m = s->mcu;
	s->shifting = 1;
	s->shift_byte = byte;
	s->shift_start = when;
	s->shift_end = when + s->frame_cycles;
	/* the receiver samples the middle of the first stop bit and raises RXC
	 * there (datasheet, "Asynchronous Data Reception") */
	uint32_t stop_bits = s->format >> 6;
	uint64_t mid_stop = s->shift_end - (uint64_t)s->bit_cycles * stop_bits + s->bit_cycles / 2;
	m162_usart_log(s, (m162_txrec_t){ m162_to_cluster(m, when), m162_to_cluster(m, mid_stop),
			m162_to_cluster(m, s->shift_end), byte, s->format,
			m162_bit_time(m, s->bit_cycles) });
}

static avr_cycle_count_t tx_done(avr_t *avr, avr_cycle_count_t when, void *param)
{
	m162_usart_t *s = (m162_usart_t *)param;
	avr_uart_t *u = s->u;
	if (s->udr_full) {
		/* the byte waiting in UDR starts as the previous stop bit ends */
		s->udr_full = 0;
		start_frame(s, s->udr_byte, when);
		avr_raise_interrupt(avr, &u->udrc);
		return s->shift_end;
	}
	s->shifting = 0;
	avr_raise_interrupt(avr, &u->txc);
	return 0;
}

static void udr_write(avr_t *avr, avr_io_addr_t addr, uint8_t v, void *param)
{
	m162_usart_t *s = (m162_usart_t *)param;
	avr_uart_t *u = s->u;
	(void)addr;
	if (!avr_regbit_get(avr, u->txen))
		return; /* transmitter off: the write goes nowhere */
	if (!s->shifting) {
		start_frame(s, v, avr->cycle);
		avr_cycle_timer_register(avr, s->frame_cycles, tx_done, s);
		/* UDR is empty again at once: UDRE stays set; re-request the
		 * (level) interrupt if it is enabled */
		avr_raise_interrupt(avr, &u->udrc);
	} else if (!s->udr_full) {
		s->udr_full = 1;
		s->udr_byte = v;
		clear_flag(avr, &u->udrc);
	}
	/* else: UDR written while UDRE is clear -- the hardware loses it */
}

/* ---------------------------------------------------------------- */
/* receiver */

int m162_usart_put(m162_usart_t *s, uint16_t value)
{
	avr_t *avr = s->mcu->avr;
	avr_uart_t *u = s->u;
	if (!avr_regbit_get(avr, u->rxen)) {
		s->rx_dropped++;
		return 0;
	}
	if (uart_fifo_get_read_size(&u->input) >= RX_CAPACITY) {
		avr_regbit_set(avr, u->dor);
		s->rx_dropped++;
		return 0;
	}
	uart_fifo_write(&u->input, value);
	avr_raise_interrupt(avr, &u->rxc);
	return 1;
}

static uint8_t udr_read(avr_t *avr, avr_io_addr_t addr, void *param)
{
	m162_usart_t *s = (m162_usart_t *)param;
	avr_uart_t *u = s->u;
	uint8_t v = 0;
	if (avr_regbit_get(avr, u->rxen) && !uart_fifo_isempty(&u->input)) {
		v = (uint8_t)(uart_fifo_read(&u->input) & 0xFF);
		if (uart_fifo_isempty(&u->input))
			clear_flag(avr, &u->rxc);
		else
			avr_raise_interrupt(avr, &u->rxc); /* RXC is a level: ask again */
		if (uart_fifo_get_read_size(&u->input) < RX_CAPACITY)
			avr_regbit_clear(avr, u->dor);
	}
	avr->data[addr] = v;
	return v;
}

/* A wire byte at its due cycle.  A receiver that came on after the byte's
 * start bit (RXEN set again, or after a reset) lost what it had of it: it
 * reads the sender's line from there, and only a falling edge at or after
 * that point is a start bit (uart_line_read's since), as on the IR medium
 * (ir_medium.h); no start bit: nothing.  Off now: m162_usart_put drops it. */
static void wire_put(m162_usart_t *s, const m162_rxpend_t *p)
{
	uint16_t v = p->value;
	if (s->rx_on && s->rx_since > p->start && (p->format & 0x3F) == (s->format & 0x3F)) {
		uart_edge_t wave[UART_LINE_BYTE_MAX];
		int n = uart_line_levels(wave, p->byte, p->format, (double)p->start, p->bit);
		int got = uart_line_read(wave, n, m162_bit_time(s->mcu, s->bit_cycles), s->format,
				(double)s->rx_since);
		if (!p->frame_ok)
			got = uart_line_out_of_range(got, p->byte, p->format);
		if (got < 0)
			return;
		v = (uint16_t)got;
	}
	m162_usart_put(s, v);
}

static avr_cycle_count_t rx_deliver(avr_t *avr, avr_cycle_count_t when, void *param)
{
	m162_usart_t *s = (m162_usart_t *)param;
	(void)avr;
	while (s->rxq_len && s->rxq[s->rxq_head].due <= when) {
		wire_put(s, &s->rxq[s->rxq_head]);
		s->rxq_head = (s->rxq_head + 1) % M162_RXQ_SIZE;
		s->rxq_len--;
	}
	return s->rxq_len ? s->rxq[s->rxq_head].due : 0;
}

void m162_usart_queue_rx(m162_usart_t *s, const m162_txrec_t *r, uint16_t value, int frame_ok)
{
	avr_t *avr = s->mcu->avr;
	uint64_t due = m162_to_local(s->mcu, r->mid_stop);
	m162_rxpend_t pend = { due < avr->cycle ? avr->cycle : due, value, r->start, r->bit,
		r->byte, r->format, (uint8_t)(frame_ok != 0) };
	if (due <= avr->cycle && s->rxq_len == 0) {
		wire_put(s, &pend);
		return;
	}
	if (s->rxq_len == M162_RXQ_SIZE) {
		s->rx_dropped++; /* a wire cannot carry this many bytes per quantum */
		return;
	}
	unsigned tail = (s->rxq_head + s->rxq_len) % M162_RXQ_SIZE;
	s->rxq[tail] = pend;
	s->rxq_len++;
	if (s->rxq_len == 1)
		avr_cycle_timer_register(avr, s->rxq[tail].due - avr->cycle, rx_deliver, s);
}

/* The receiver came on or went off (RXEN, or a reset): log it for the IR
 * medium (its own receiver reads from there) and for Python (uart_rx_log). */
static void note_rx(m162_usart_t *s, int on)
{
	m162_t *m = s->mcu;
	if (on == s->rx_on)
		return;
	s->rx_on = on;
	uint64_t now = m162_to_cluster(m, m->avr->cycle);
	if (on)
		s->rx_since = now;
	if (m->ir)
		ir_note_rx(m->ir, s, now, on);
	if (s->rx_log_len == 64) { /* nobody takes them: keep the latest, count the loss */
		memmove(s->rx_log, s->rx_log + 1, 63 * sizeof *s->rx_log);
		s->rx_log_len--;
		s->rx_log_lost++;
	}
	if (GROW(s->rx_log, s->rx_log_len, s->rx_log_cap, 4) == 0)
		s->rx_log[s->rx_log_len++] = (m162_rxmark_t){ now, on };
	m->changed = 1;
}

/* ---------------------------------------------------------------- */
/* control registers */

static void ctrl_write(avr_t *avr, avr_io_addr_t addr, uint8_t v, void *param)
{
	m162_usart_t *s = (m162_usart_t *)param;
	avr_uart_t *u = s->u;
	int had_rxcie = avr_regbit_get(avr, u->rxc.enable);
	/* simavr's avr_uart_write serves both UCSRnA and UCSRnB */
	s->orig_ucsrb_write(avr, addr, v, s->orig_ucsrb_write_param);
	/* simavr raises UDRE whenever UDRIE is switched on; not while a byte
	 * waits in UDR */
	if (s->udr_full && udrie(avr, u))
		clear_flag(avr, &u->udrc);
	/* RXC is a level: enabling RXCIE with data waiting interrupts at once */
	if (!had_rxcie && avr_regbit_get(avr, u->rxc.enable) && !uart_fifo_isempty(&u->input))
		avr_raise_interrupt(avr, &u->rxc);
	note_rx(s, avr_regbit_get(avr, u->rxen));
	recompute_frame(s);
}

static void ubrrl_write(avr_t *avr, avr_io_addr_t addr, uint8_t v, void *param)
{
	m162_usart_t *s = (m162_usart_t *)param;
	avr->data[addr] = v;
	recompute_frame(s);
}

static void shared_write(avr_t *avr, avr_io_addr_t addr, uint8_t v, void *param)
{
	m162_usart_t *s = (m162_usart_t *)param;
	(void)addr;
	if (v & URSEL)
		avr->data[s->ucsrc_addr] = v; /* URSEL reads back as 1 */
	else
		avr->data[s->ubrrh_addr] = v & 0x0F; /* bits 6..4 reserved */
	recompute_frame(s);
}

static uint8_t shared_read(avr_t *avr, avr_io_addr_t addr, void *param)
{
	m162_usart_t *s = (m162_usart_t *)param;
	uint8_t v = s->last_shared_read == avr->cycle ? avr->data[s->ucsrc_addr]
			: avr->data[s->ubrrh_addr];
	s->last_shared_read = avr->cycle + 1;
	avr->data[addr] = v;
	return v;
}

void m162_usart_init(m162_t *m)
{
	avr_t *avr = m->avr;
	for (int i = 0; i < M162_NUARTS; i++) {
		m162_usart_t *s = &m->usart[i];
		avr_uart_t *u = s->u;
		u->flags = 0; /* no stdout echo, no usleep() on polls */

		avr->io[IO(u->r_udr)].w.c = udr_write;
		avr->io[IO(u->r_udr)].w.param = s;
		avr->io[IO(u->r_udr)].r.c = udr_read;
		avr->io[IO(u->r_udr)].r.param = s;

		/* simavr registered avr_uart_write on UCSRnA and UCSRnB */
		s->orig_ucsrb_write = avr->io[IO(u->r_ucsrb)].w.c;
		s->orig_ucsrb_write_param = avr->io[IO(u->r_ucsrb)].w.param;
		avr->io[IO(u->r_ucsrb)].w.c = ctrl_write;
		avr->io[IO(u->r_ucsrb)].w.param = s;
		avr->io[IO(u->r_ucsra)].w.c = ctrl_write;
		avr->io[IO(u->r_ucsra)].w.param = s;

		avr->io[IO(u->ubrrl.reg)].w.c = ubrrl_write;
		avr->io[IO(u->ubrrl.reg)].w.param = s;

		avr->io[IO(s->shared_addr)].w.c = shared_write;
		avr->io[IO(s->shared_addr)].w.param = s;
		avr->io[IO(s->shared_addr)].r.c = shared_read;
		avr->io[IO(s->shared_addr)].r.param = s;
	}
}

void m162_usart_reset(m162_t *m)
{
	avr_t *avr = m->avr;
	for (int i = 0; i < M162_NUARTS; i++) {
		m162_usart_t *s = &m->usart[i];
		avr_uart_t *u = s->u;
		/* simavr turns TXEN on at reset "to allow printf"; the part does not */
		avr_regbit_clear(avr, u->txen);
		avr->data[s->ucsrc_addr] = 0x86; /* URSEL=1, 8 data bits, async */
		avr->data[s->ubrrh_addr] = 0;
		avr->data[s->shared_addr] = 0;
		avr_regbit_set(avr, u->udrc.raised);
		s->shifting = 0;
		s->udr_full = 0;
		s->last_shared_read = 0;
		note_rx(s, 0); /* a byte on its way in is lost (the medium reads on) */
		recompute_frame(s);
		/* wire bytes on their way in stay queued: the receiver reads what
		 * it can of them from where it comes on again (wire_put); simavr
		 * has cleared the MCU's timers before this hook runs */
		if (s->rxq_len) {
			uint64_t due = s->rxq[s->rxq_head].due;
			avr_cycle_timer_register(avr, due > avr->cycle ? due - avr->cycle : 0,
					rx_deliver, s);
		}
	}
}

void m162_usart_config(m162_usart_t *s, double *baud, int *data_bits, char *parity,
		int *stop_bits, int *rxen, int *txen)
{
	avr_t *avr = s->mcu->avr;
	avr_uart_t *u = s->u;
	static const int databits[8] = { 5, 6, 7, 8, 8, 8, 8, 9 };
	uint32_t ubrr = avr->data[u->ubrrl.reg] | ((avr->data[s->ubrrh_addr] & 0x0F) << 8);
	uint32_t cpb = (ubrr + 1) * (avr_regbit_get(avr, u->u2x) ? 8 : 16);
	int upm = (avr->data[s->ucsrc_addr] >> 4) & 3;
	*baud = (double)avr->frequency / cpb;
	*data_bits = databits[avr_regbit_get(avr, u->ucsz) | (avr_regbit_get(avr, u->ucsz2) << 2)];
	*parity = upm == 2 ? 'E' : upm == 3 ? 'O' : 'N';
	*stop_bits = 1 + avr_regbit_get(avr, u->usbs);
	*rxen = avr_regbit_get(avr, u->rxen);
	*txen = avr_regbit_get(avr, u->txen);
}

void m162_usart_set_keep_log(m162_usart_t *s, int keep)
{
	s->keep_log = keep;
}

int m162_usart_frame_ok(const m162_usart_t *s, const m162_txrec_t *r, double tolerance)
{
	/* a receiver checks only the first stop bit: 8N2 into 8N1 is fine */
	if ((r->format & 0x3F) != (s->format & 0x3F))
		return 0;
	double sent = r->bit, own = m162_bit_time(s->mcu, s->bit_cycles);
	double diff = sent > own ? sent - own : own - sent;
	return diff <= tolerance * sent;
}

/* One byte of r, sent at its rate, as a receiver set up as s reads it (the
 * same word format, another bit time): uart_line_read of the sender's
 * levels.  Only the first byte: the medium delivers one byte per byte sent.
 * Called only outside the baud tolerance, so the sent byte never arrives
 * as good.  -1: the start bit is over before the receiver samples it (a
 * glitch, no byte); else the byte, with UART_INPUT_FE when its stop bit
 * reads low.  The same reading as hil_sim/uart_line.py's first_byte (a test
 * compares them). */
int m162_usart_resample(const m162_usart_t *s, const m162_txrec_t *r)
{
	uart_edge_t wave[UART_LINE_BYTE_MAX];
	int n = uart_line_levels(wave, r->byte, r->format, 0, r->bit);
	int got = uart_line_read(wave, n, m162_bit_time(s->mcu, s->bit_cycles), r->format, -1.0);
	return uart_line_out_of_range(got, r->byte, r->format);
}

/* Forget records every consumer has seen, so logs stay small. */
void m162_usart_compact_log(m162_usart_t *s)
{
	size_t low = s->log_len;
	if (s->peer && s->wire_pos < low)
		low = s->wire_pos;
	if (s->watched && s->take_pos < low)
		low = s->take_pos;
	if (s->watched && s->notified_pos < low)
		low = s->notified_pos;
	if (s->mcu->ir && s->ir_sel_port >= 0 && s->ir_pos < low)
		low = s->ir_pos;
	if (low == 0)
		return;
	memmove(s->log, s->log + low, (s->log_len - low) * sizeof *s->log);
	s->log_len -= low;
	s->wire_pos = s->wire_pos > low ? s->wire_pos - low : 0;
	s->take_pos = s->take_pos > low ? s->take_pos - low : 0;
	s->notified_pos = s->notified_pos > low ? s->notified_pos - low : 0;
	s->ir_pos = s->ir_pos > low ? s->ir_pos - low : 0;
}
