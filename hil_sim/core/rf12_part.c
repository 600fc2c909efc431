/*
 * rf12_part.c -- the RF12 transceiver as a part on an MCU's pins.
 * See rf12_part.h; the command words follow the RF12 datasheet (HOPERF
 * RF12, "Control commands"), the subset the thesis' listing uses plus
 * software reset.  Decisions (documented in docs/simulator.md, "Radio"):
 * - SDO presents bit 15-n after the n-th rising SCK edge (the driver samples
 *   right after raising SCK); the status word is latched at the first edge
 *   of a word whose first bit is 0, the FIFO byte at the 8th edge of 0xB0xx.
 * - A word takes effect when nSEL rises after exactly 16 bits.
 * - The transmit register holds 0xAAAA when the transmitter is switched on
 *   (two preamble bytes); RGIT (nIRQ low) while the latch is free.  An
 *   underrun sets RGUR and sends the last byte again.
 * - Sync detection and FIFO work on whole bytes as the transmitter framed
 *   them (the medium is byte-aligned); an empty air gives no noise bytes.
 */
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include "rf12_part.h"
#include "sim_cycle_timers.h"

#define RF12_XTAL_HZ 10000000ull
#define SYNC_HIGH 0x2D

/* power management bits (0x82xx) */
#define PWR_ER 0x80
#define PWR_ET 0x20
/* configuration bits (0x80xx) */
#define CFG_EL 0x80
#define CFG_EF 0x40
/* FIFO and reset mode bits (0xCAxx) */
#define FIFO_FF 0x02
#define FIFO_AL 0x04

static uint64_t now_cluster(const rf12_t *r)
{
	return m162_to_cluster(r->m, r->m->avr->cycle);
}

/* Cluster cycles from the start of transmission to the end of byte k. */
static uint64_t byte_end(const rf12_t *r, uint64_t k)
{
	uint64_t div = 29ull * ((r->rate & 0x7F) + 1) * ((r->rate & 0x80) ? 8 : 1);
	return r->tx_origin + (k + 1) * 8 * r->m->clock.nominal_hz * div / RF12_XTAL_HZ;
}

static int fifo_interrupt(const rf12_t *r)
{
	int level = (r->fifo_mode >> 4) & 0x0F;
	int bytes = level > 8 ? 2 : 1;
	return (r->power & PWR_ER) && r->fifo_len >= bytes;
}

static int tx_ready(const rf12_t *r)
{
	return r->tx_on && !r->tx_latch_full;
}

/* nIRQ is low while any interrupt source is active. */
static void update_irq(rf12_t *r)
{
	int active = r->por || r->ffov || r->rgur || tx_ready(r) || fifo_interrupt(r);
	uint8_t level = active ? 0 : 1;
	if (level == r->irq_level)
		return;
	r->irq_level = level;
	m162_drive_input(r->m, r->pins.irq_port, 1u << r->pins.irq, level << r->pins.irq);
}

static void set_sdo(rf12_t *r, int bit)
{
	m162_drive_input(r->m, r->pins.spi_port, 1u << r->pins.sdo, (bit ? 1u : 0u) << r->pins.sdo);
}

static uint16_t status_word(rf12_t *r)
{
	uint16_t s = 0;
	if (tx_ready(r) || fifo_interrupt(r))
		s |= 0x8000;
	if (r->por)
		s |= 0x4000;
	if (r->rgur || r->ffov)
		s |= 0x2000;
	if (!r->fifo_len)
		s |= 0x0200;
	if (r->synced)
		s |= 0x0080; /* DQD: good data quality while a packet is framed */
	/* reading the status clears the latched interrupts */
	r->por = r->ffov = r->rgur = 0;
	return s;
}

static uint8_t fifo_pop(rf12_t *r)
{
	if (!r->fifo_len)
		return 0;
	uint8_t b = r->fifo[0];
	r->fifo[0] = r->fifo[1];
	r->fifo_len--;
	return b;
}

/* ---- transmitter ---------------------------------------------------- */

static void log_byte(rf12_t *r, uint64_t end, int cut)
{
	if (r->log_len == RF12_LOG_SIZE) { /* Python fell behind: drop the oldest */
		r->log_head = (r->log_head + 1) % RF12_LOG_SIZE;
		r->log_len--;
		r->log_dropped++;
	}
	rf12_airbyte_t *b = &r->log[(r->log_head + r->log_len++) % RF12_LOG_SIZE];
	*b = (rf12_airbyte_t){ r->tx_byte_start, end, r->tx_byte, (uint8_t)cut, r->channel };
	r->news = 1;
}

static void arm(rf12_t *r, uint64_t due_cluster, avr_cycle_timer_t fn, void *param)
{
	uint64_t due = m162_to_local(r->m, due_cluster), now = r->m->avr->cycle;
	avr_cycle_timer_register(r->m->avr, due > now ? due - now : 1, fn, param);
}

static avr_cycle_count_t tx_byte_done(avr_t *avr, avr_cycle_count_t when, void *param);

static void tx_arm(rf12_t *r)
{
	arm(r, byte_end(r, r->tx_count), tx_byte_done, &r->tx_on);
}

static avr_cycle_count_t tx_byte_done(avr_t *avr, avr_cycle_count_t when, void *param)
{
	(void)avr;
	(void)when;
	rf12_t *r = (rf12_t *)((char *)param - offsetof(rf12_t, tx_on));
	uint64_t end = byte_end(r, r->tx_count);
	log_byte(r, end, 0);
	if (r->tx_latch_full) {
		r->tx_byte = r->tx_latch;
		r->tx_latch_full = 0;
	} else {
		r->rgur = 1; /* underrun: the last byte goes out again */
	}
	r->tx_count++;
	r->tx_byte_start = end;
	tx_arm(r);
	update_irq(r);
	return 0;
}

static void tx_start(rf12_t *r)
{
	r->tx_on = r->tx_shifting = 1;
	r->tx_byte = r->tx_latch = 0xAA; /* the register holds 0xAAAA */
	r->tx_latch_full = 1;
	r->tx_origin = r->tx_byte_start = now_cluster(r);
	r->tx_count = 0;
	r->news = 1; /* a new carrier: Python learns when its bytes end */
	tx_arm(r);
}

static void tx_stop(rf12_t *r)
{
	if (r->tx_shifting) {
		uint64_t now = now_cluster(r);
		if (now > r->tx_byte_start)
			log_byte(r, now, 1);
		avr_cycle_timer_cancel(r->m->avr, tx_byte_done, &r->tx_on);
	}
	r->tx_on = r->tx_shifting = r->tx_latch_full = 0;
}

/* ---- receiver ------------------------------------------------------- */

static void fifo_reset(rf12_t *r)
{
	r->synced = 0;
	r->sync_seen = 0;
	r->fifo_len = 0;
}

static void rx_byte(rf12_t *r, uint8_t b)
{
	if (!(r->power & PWR_ER) || !(r->config & CFG_EF) || !(r->fifo_mode & FIFO_FF)) {
		r->rx_dropped++;
		return;
	}
	if (!r->synced && (r->fifo_mode & FIFO_AL))
		r->synced = 1;
	if (!r->synced) {
		r->synced = r->sync_seen && b == r->sync_low;
		r->sync_seen = b == SYNC_HIGH;
		return;
	}
	if (r->fifo_len == 2) {
		r->ffov = 1;
		r->rx_dropped++;
		return;
	}
	r->fifo[r->fifo_len++] = b;
}

static avr_cycle_count_t rx_due(avr_t *avr, avr_cycle_count_t when, void *param);

static void rx_arm(rf12_t *r)
{
	if (r->rxq_len)
		arm(r, r->rxq[r->rxq_head].due, rx_due, r->rxq);
}

static avr_cycle_count_t rx_due(avr_t *avr, avr_cycle_count_t when, void *param)
{
	(void)avr;
	(void)when;
	rf12_t *r = (rf12_t *)((char *)param - offsetof(rf12_t, rxq));
	uint64_t now = now_cluster(r);
	while (r->rxq_len && r->rxq[r->rxq_head].due <= now) {
		rx_byte(r, r->rxq[r->rxq_head].byte);
		r->rxq_head = (r->rxq_head + 1) % RF12_RXQ_SIZE;
		r->rxq_len--;
	}
	rx_arm(r);
	update_irq(r);
	return 0;
}

void rf12_deliver(rf12_t *r, uint64_t due, uint8_t byte)
{
	if (r->rxq_len == RF12_RXQ_SIZE) {
		r->rx_dropped++;
		return;
	}
	r->rxq[(r->rxq_head + r->rxq_len++) % RF12_RXQ_SIZE].due = due;
	r->rxq[(r->rxq_head + r->rxq_len - 1) % RF12_RXQ_SIZE].byte = byte;
	if (r->rxq_len == 1)
		rx_arm(r);
}

/* ---- command words -------------------------------------------------- */

static void power_on_reset(rf12_t *r)
{
	if (r->tx_shifting)
		tx_stop(r);
	/* datasheet power-on values of the registers we model */
	r->config = 0x08;
	r->power = 0x08;
	r->freq = 0x680;
	r->rate = 0x23;
	r->fifo_mode = 0x80;
	r->sync_low = 0xD4;
	r->rgur = r->ffov = 0;
	r->por = 1;
	fifo_reset(r);
}

static void update_channel(rf12_t *r)
{
	r->channel = (rf12_channel_t){ (uint8_t)((r->config >> 4) & 3), r->freq, (uint8_t)r->rate };
}

static void execute(rf12_t *r, uint16_t w)
{
	uint8_t low = w & 0xFF;
	if ((w & 0xFF00) == 0x8000) {
		r->config = low;
	} else if ((w & 0xFF00) == 0x8200) {
		int was_tx = r->power & PWR_ET;
		r->power = low;
		int tx = (low & PWR_ET) && (r->config & CFG_EL);
		if (tx && !was_tx)
			tx_start(r);
		else if (!tx && r->tx_on)
			tx_stop(r);
	} else if ((w & 0xF000) == 0xA000) {
		r->freq = w & 0x0FFF;
	} else if ((w & 0xFF00) == 0xC600) {
		r->rate = low;
	} else if ((w & 0xFF00) == 0xCA00) {
		if (!(low & FIFO_FF))
			fifo_reset(r);
		r->fifo_mode = low;
	} else if ((w & 0xFF00) == 0xCE00) {
		r->sync_low = low;
	} else if ((w & 0xFF00) == 0xB800) {
		if (r->config & CFG_EL) {
			r->tx_latch = low;
			r->tx_latch_full = 1;
		}
	} else if (w == 0xFE00) {
		power_on_reset(r);
	}
	/* other words (receiver, filter, AFC, TX power, PLL, timers, battery
	 * detector) do not change what this model does */
	update_channel(r);
}

static void sck_rise(rf12_t *r, uint8_t port)
{
	r->in = (uint16_t)((r->in << 1) | ((port >> r->pins.sdi) & 1));
	r->nbits++;
	if (r->nbits == 1 && !(r->in & 1))
		r->out = status_word(r);
	else if (r->nbits == 8 && r->in == 0xB0)
		r->out = fifo_pop(r);
	if (r->nbits <= 16)
		set_sdo(r, (r->out >> (16 - r->nbits)) & 1);
	update_irq(r);
}

static void port_written(struct avr_irq_t *irq, uint32_t value, void *param)
{
	(void)irq;
	rf12_t *r = param;
	uint8_t now = (uint8_t)value, before = r->last_port;
	r->last_port = now;
	uint8_t sel = 1u << r->pins.sel, sck = 1u << r->pins.sck;
	if ((before & sel) && !(now & sel)) { /* nSEL falls: a new word */
		r->selected = 1;
		r->nbits = 0;
		r->in = r->out = 0;
		set_sdo(r, 0);
	}
	if (r->selected && !(now & sel) && (now & sck) && !(before & sck))
		sck_rise(r, now);
	if (r->selected && (now & sel) && !(before & sel)) { /* nSEL rises */
		r->selected = 0;
		if (r->nbits == 16)
			execute(r, r->in);
		update_irq(r);
	}
}

/* An MCU reset cancels every cycle timer; the chip runs on. */
static void mcu_reset(avr_io_t *io)
{
	rf12_t *r = (rf12_t *)((char *)io - offsetof(rf12_t, io));
	if (r->tx_shifting)
		tx_arm(r);
	rx_arm(r);
	r->irq_level = 2; /* drive nIRQ again whatever simavr did to the pin */
	update_irq(r);
}

rf12_t *rf12_attach(m162_t *m, rf12_pins_t pins)
{
	rf12_t *r = calloc(1, sizeof *r);
	if (!r)
		return NULL;
	r->m = m;
	r->pins = pins;
	r->last_port = 0xFF;
	r->irq_level = 2; /* unknown: the first update drives the pin */
	power_on_reset(r);
	update_channel(r);
	r->io = (avr_io_t){ .kind = "rf12", .reset = mcu_reset };
	avr_register_io(m->avr, &r->io);
	avr_irq_t *irq = avr_io_getirq(m->avr, AVR_IOCTL_IOPORT_GETIRQ('A' + pins.spi_port),
			IOPORT_IRQ_REG_PORT);
	if (irq)
		avr_irq_register_notify(irq, port_written, r);
	set_sdo(r, 0);
	update_irq(r);
	m->rf12 = r;
	return r;
}

void rf12_free(rf12_t *r)
{
	free(r);
}

int rf12_take(rf12_t *r, rf12_airbyte_t *out, int max)
{
	int n = 0;
	while (r->log_len && n < max) {
		out[n++] = r->log[r->log_head];
		r->log_head = (r->log_head + 1) % RF12_LOG_SIZE;
		r->log_len--;
	}
	return n;
}

int rf12_carrier(const rf12_t *r, rf12_airbyte_t *out)
{
	if (!r->tx_shifting)
		return 0;
	*out = (rf12_airbyte_t){ r->tx_byte_start, byte_end(r, r->tx_count), r->tx_byte, 0,
		r->channel };
	return 1;
}

int rf12_news(rf12_t *r)
{
	int news = r->news;
	r->news = 0;
	return news;
}

int rf12_receiving(const rf12_t *r)
{
	return (r->power & PWR_ER) != 0;
}
