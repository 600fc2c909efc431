/*
 * ir_medium.h -- the IR medium between communication boards, routed in C.
 *
 * Each comm board's UART1 drives one of seven IR transceivers, chosen by its
 * channel selector (Table 3-5).  Python (hil_sim/simulator.py) attaches each
 * comm board's UART1 and gives, per board, a route for each selector index
 * Y = 4C + 2B + A: nowhere, the PC (the centre channel), or another board
 * that hears the byte only while its own selector is on a given index (the
 * side facing the sender).  Python re-sends the routes whenever the plant
 * changes the geometry; the core knows nothing of cells or sides.
 *
 * Timing, decided here and not by the quantum:
 *  - the sender's side is its selector index at the byte's start bit, a
 *    write on that very cycle included (the write wins the tie: a byte that
 *    waited in UDR leaves by the new side), from its own selector history
 *    at the boundary after the start;
 *  - a receiver gets the byte in the middle of its stop bit, where the part
 *    samples it and raises RXC (or at the next boundary, below);
 *  - a byte is cut where the sender's selector left the byte's channel or
 *    the sender reset, and where the receiver's selector was elsewhere: the
 *    receiver reads what its UART samples of the part it saw, idle high
 *    around it (ir_line.c).  Only the part before the stop bit counts: from
 *    there on the line is high either way.  Selector changes and resets are
 *    noted by the MCU's own run (ir_note_port, ir_note_reset) and published
 *    to the other MCUs at the next boundary; a receiver reads its own
 *    history to the cycle and a sender's as of the boundary before its own
 *    quantum.  When that boundary is before the byte's stop bit (a quantum
 *    longer than half a bit), the byte waits for the next boundary, so what
 *    a receiver reads never depends on the quantum;
 *  - a receiver whose own USART was off for part of a byte (RXEN cleared,
 *    or its MCU reset) lost what it had of it: it reads the line from where
 *    it came on last, looking for a falling edge there (a line already low
 *    is no start bit; uart_line_read), and one that is off at the byte's
 *    horizon, the middle of its stop bit by the sender's bit time (stop +
 *    bit / 2), does not get it (ir-dropped).  Its own on/off changes
 *    (ir_note_rx) count up to that horizon; the byte is handed over once
 *    the receiver's run has passed it, so they are all known;
 *  - two bytes from different senders that overlap in time at one receiver
 *    collide: the second is handed over, with the framing error flag, as
 *    what the receiver's UART samples of the AND of both lines, each at its
 *    real start (the bitwise AND when both started together, whole; as
 *    hil_sim/ir_bus.py);
 *  - a receiver whose bit time is more than the cluster's baud tolerance
 *    away reads what its UART samples (a byte it still reads right keeps a
 *    framing error, whole or cut: uart_line_out_of_range); one whose word
 *    format differs gets a byte of its own seeded generator with the
 *    framing error flag.
 * Bytes for the PC wait until their stop bit ended and go to Python
 * (ir_take_pc), which owns the PC's receiver; run() returns at the boundary
 * after one ends.  The PC's own bytes come from Python (ir_send_from_pc).
 * Collisions, dropped and garbled bytes are logged as events for Python.
 *
 * Everything a receiver does happens in its own run or at a boundary, so the
 * result does not depend on the order (or threads) MCUs are stepped in.
 */
#ifndef HEXBOT_IR_MEDIUM_H
#define HEXBOT_IR_MEDIUM_H

#include <stddef.h>
#include <stdint.h>

#include "cluster.h"
#include "ir_line.h"

enum { IR_ROUTE_NONE = 0, IR_ROUTE_PC = 1, IR_ROUTE_MODULE = 2 };
enum { IR_EV_COLLISION = 1, IR_EV_DROPPED = 2, IR_EV_GARBLED = 3 };

#define IR_PC (-1)          /* the PC as a sender */
#define IR_MAX_SENDERS 8    /* six neighbours, the PC, one spare */
#define IR_INBOX 64         /* bytes in flight towards one receiver */

/* A change of a board's selector index (0..7), or its reset (IR_MARK_RESET:
 * the USART stops shifting), at a cluster cycle. */
enum { IR_MARK_RESET = -1 };
typedef struct ir_mark_t {
	uint64_t cycle;
	int y;
} ir_mark_t;

typedef struct ir_route_t {
	int kind;   /* IR_ROUTE_* */
	int target; /* receiver MCU index (IR_ROUTE_MODULE) */
	int need_y; /* the receiver's selector index that faces the sender */
} ir_route_t;

/* One byte on its way to one receiver. */
typedef struct ir_air_t {
	uint64_t start, due, end; /* cluster cycles; due = middle of the stop bit */
	uint64_t due_local;       /* due in the receiver's own cycles */
	int sender;               /* MCU index or IR_PC */
	const struct ir_port_t *from; /* the sender's port, NULL for the PC */
	uint8_t byte, format, need_y;
	int8_t sent_y;            /* the sender's selector index at the start bit */
	double bit;               /* the sender's bit time, cluster cycles (m162_bit_time) */
	double stop;              /* where its stop bit begins (ir_part_stop) */
} ir_air_t;

typedef struct ir_event_t {
	uint64_t end;      /* the byte's end: Python stamps IR events with it */
	uint64_t seq;      /* order of events at one receiver */
	int kind, sender, receiver;
	uint8_t byte;
	int others[IR_MAX_SENDERS]; /* senders the byte collided with */
	int n_others;
} ir_event_t;

typedef struct ir_pcbyte_t {
	uint64_t start, end;
	uint8_t byte;
} ir_pcbyte_t;

typedef struct ir_port_t {
	/* what every boundary reads first, in one cache line: with hundreds of
	 * MCUs the boundary's cost is its cache misses */
	m162_usart_t *s;
	int inbox_len;
	int sel_port;         /* 0..4 = A..E */
	size_t n_pc, pc_notified;
	size_t n_fresh, n_marks; /* selector history (below), read by publish() */
	m162_t *m;
	int index;            /* MCU index in the cluster */
	int centre_y;         /* selector index that routes to the PC, -1 none */
	uint8_t sel_bits[3];  /* bits of the selector lines A, B, C */
	double tolerance;
	ir_route_t routes[8];
	/* receiver */
	uint64_t overflow;    /* bytes lost because the inbox was full */
	struct {
		int valid, fe, n;
		uint64_t start, end;
		int senders[IR_MAX_SENDERS];
		ir_part_t parts[IR_MAX_SENDERS]; /* their lines, for a collision */
		uint8_t value;
	} last;               /* what the receiver made of the last byte(s) */
	uint64_t rng;         /* garbage for mismatched frames */
	ir_event_t *events;
	size_t n_events, cap_events;
	uint64_t seq;
	/* sender: bytes on the centre channel, for the PC */
	ir_pcbyte_t *to_pc;
	size_t cap_pc;
	/* selector history: the MCU's own run appends to fresh; the boundary
	 * moves fresh to marks, which other MCUs' runs read (never the other
	 * way: no MCU reads what another is writing in the same quantum) */
	ir_mark_t *fresh, *marks;
	size_t cap_fresh, cap_marks;
	int y_before;         /* the selector index before the first mark */
	int y_now;            /* the last index noted */
	uint64_t longest;     /* longest frame sent or heard: how long marks are kept */
	uint64_t published;   /* the last boundary: every board's marks before it are in marks */
	/* its USART receiver's on/off changes (ir_note_rx), read by its own run
	 * and pruned at the boundary, as its own selector marks */
	m162_rxmark_t *rx;
	size_t n_rx, cap_rx;
	int rx_before_on;     /* the state before rx[0] */
	uint64_t rx_before_since; /* and since when it was on, if it was */
	ir_air_t inbox[IR_INBOX]; /* sorted by due */
} ir_port_t;

/* Attach MCU mcu's USART uart to the medium; the selector lines A, B, C are
 * bits sel_bits of port sel_port.  Returns 0, or -1 (out of memory). */
int ir_attach(cluster_t *c, int mcu, int uart, int sel_port, const uint8_t sel_bits[3]);
void ir_set_routes(cluster_t *c, int mcu, const ir_route_t routes[8]);
void ir_set_seed(cluster_t *c, uint64_t seed);
/* A byte of the PC's transceiver (start..end, cluster cycles): reaches every
 * attached board whose selector is on the centre in the middle of its stop bit. */
void ir_send_from_pc(cluster_t *c, uint64_t start, uint64_t end, uint8_t byte,
		uint8_t format);
/* Work at a quantum boundary; 1 if a byte for the PC ended. */
int ir_boundary(cluster_t *c);
/* Bytes for the PC whose stop bit ended by now, of MCU mcu (removed). */
size_t ir_take_pc(ir_port_t *p, uint64_t now, ir_pcbyte_t *out, size_t max);
void ir_free(ir_port_t *p);

#endif
