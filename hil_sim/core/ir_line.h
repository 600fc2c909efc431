/*
 * ir_line.h -- what a receiver's UART reads of the IR line when bytes are
 * cut or overlap.  The twin of hil_sim/ir_line.py (see its docstring for the
 * rules): a byte is seen only in its spans (the sender's selector still on
 * the byte's channel, no reset since, the receiver's on the facing side);
 * outside them the line idles high; overlapping bytes are the AND of their
 * levels, each at its real start; uart_line_read samples the result.
 * Times are cluster cycles.
 */
#ifndef HEXBOT_IR_LINE_H
#define HEXBOT_IR_LINE_H

#include <stdint.h>

/* Spans kept per byte: a selector that leaves and comes back more often
 * within one byte shows the byte only in its first IR_MAX_SPANS spans
 * (ir_line.py MAX_SPANS, the same). */
#define IR_MAX_SPANS 4

typedef struct ir_span_t {
	double from, to; /* [from, to) */
} ir_span_t;

typedef struct ir_part_t {
	double start, end, bit; /* start bit, end of the stop bit, sender's bit time */
	uint8_t byte, format;   /* format of the sender (m162_txrec_t.format) */
	int n_spans;
	ir_span_t spans[IR_MAX_SPANS];
} ir_part_t;

/* Where its stop bit begins (ir_line.py stop_bit).  From there on its line
 * is high whether the receiver sees it or not, so its spans end there. */
double ir_part_stop(const ir_part_t *p);
/* The receiver saw all of it up to the stop bit: nothing was cut. */
int ir_part_whole(const ir_part_t *p);
/* Spans in both a and b, in order, at most IR_MAX_SPANS into out; how many. */
int ir_spans_intersect(ir_span_t *out, const ir_span_t *a, int na, const ir_span_t *b, int nb);
/* The first byte a receiver with bit time bit and format reads of the line
 * of parts[0..n): byte | UART_INPUT_FE, or -1 (no start bit).  since: the
 * receiver came on there, and looks for a falling edge from there on
 * (uart_line_read); -1: on all along. */
int ir_line_read(const ir_part_t *parts, int n, double bit, uint8_t format, double since);

#endif
