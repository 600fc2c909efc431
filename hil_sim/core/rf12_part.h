/*
 * rf12_part.h -- an RF12 (433/868/915 MHz FSK transceiver) as a part on an
 * MCU's pins: the 16-bit command words clocked in on nSEL/SCK/SDI, status
 * and FIFO bytes clocked out on SDO, the nIRQ line, the transmit register
 * and the receive FIFO.  The air between radios is Python's
 * (hil_sim/radio.py): this part logs the bytes it sends, in cluster cycles,
 * and takes the bytes the medium delivers at their due cycle.
 *
 * Like simavr's parts it only talks through IRQ signals: it listens to the
 * PORT register of the SPI port and drives SDO and nIRQ as external inputs.
 * Its clock is the chip's own 10 MHz crystal, so byte times are counted in
 * cluster cycles (the nominal clock), whatever the MCU's own clock.
 */
#ifndef HEXBOT_RF12_PART_H
#define HEXBOT_RF12_PART_H

#include <stdint.h>

#include "m162.h"

/* The channel a byte went out on: receivers hear only the same one. */
typedef struct rf12_channel_t {
	uint8_t band;   /* 1 = 433, 2 = 868, 3 = 915 MHz (0x80xx b1..b0) */
	uint16_t freq;  /* frequency word F (0xAxxx) */
	uint8_t rate;   /* data rate command byte cs|R (0xC6xx) */
} rf12_channel_t;

/* One byte on the air, in cluster cycles.  end is where its last bit ends,
 * or where the transmitter was switched off (cut = 1). */
typedef struct rf12_airbyte_t {
	uint64_t start, end;
	uint8_t byte, cut;
	rf12_channel_t channel;
} rf12_airbyte_t;

typedef struct rf12_pins_t {
	int spi_port, sel, sdi, sdo, sck; /* port index 0..4 (A..E), bits */
	int irq_port, irq;
} rf12_pins_t;

#define RF12_LOG_SIZE 64
#define RF12_RXQ_SIZE 64

typedef struct rf12_t {
	m162_t *m;
	rf12_pins_t pins;
	avr_io_t io; /* re-arms the chip's timers after an MCU reset */
	uint8_t last_port;
	/* SPI shift state of the word being clocked in */
	int selected, nbits;
	uint16_t in, out;
	/* configuration registers (the command words' payloads) */
	uint16_t config, power, freq, rate, fifo_mode, sync_low;
	rf12_channel_t channel;
	/* status */
	int por, ffov, rgur;
	/* transmitter: the byte shifting out and a one-byte latch */
	int tx_on, tx_latch_full, tx_shifting;
	uint8_t tx_latch, tx_byte;
	uint64_t tx_byte_start;   /* cluster cycle the shifting byte started */
	uint64_t tx_origin;       /* bytes are timed from here ... */
	uint64_t tx_count;        /* ... this many bytes ago */
	rf12_airbyte_t log[RF12_LOG_SIZE];
	unsigned log_head, log_len;
	int news; /* bytes logged since the cluster last looked */
	uint64_t log_dropped;
	/* receiver: bytes in flight from the medium, sync search, the FIFO */
	struct { uint64_t due; uint8_t byte; } rxq[RF12_RXQ_SIZE];
	unsigned rxq_head, rxq_len;
	uint8_t sync_seen; /* 1 after 0x2D in the sync search */
	int synced;
	uint8_t fifo[2];
	int fifo_len;
	uint64_t rx_dropped;
	uint8_t irq_level; /* what nIRQ is driven to now */
} rf12_t;

/* Attach a radio to MCU m on these pins; NULL if out of memory. */
rf12_t *rf12_attach(m162_t *m, rf12_pins_t pins);
/* Free after the MCU (its io list points into the part). */
void rf12_free(rf12_t *r);
/* Bytes whose air time is over, oldest first, each once; returns how many
 * were copied into out (at most max). */
int rf12_take(rf12_t *r, rf12_airbyte_t *out, int max);
/* The byte on the air now, if any (1 and *out filled; its end is where it
 * would end if the transmitter stays on). */
int rf12_carrier(const rf12_t *r, rf12_airbyte_t *out);
/* Did a byte end since the last call? (the cluster returns to Python) */
int rf12_news(rf12_t *r);
/* A byte from the air, complete at cluster cycle due. */
void rf12_deliver(rf12_t *r, uint64_t due, uint8_t byte);
/* 1 if the receiver chain is on (power management er). */
int rf12_receiving(const rf12_t *r);

#endif
