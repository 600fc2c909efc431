/*
 * uart_line.h -- what a UART reads of a serial line's levels.
 *
 * The twin of hil_sim/uart_line.py (levels, read_first): a line is a list of
 * (time a level begins, level), idle high from its last entry on; a
 * receiver waits for the line low, checks the start bit in its middle (a
 * glitch re-arms there) and samples each data bit and the stop bit in its
 * middle.  One sampling rule for the whole core: a receiver at another baud
 * rate (m162_usart_resample) and the IR medium's cut and colliding bytes
 * (ir_line.c) both read through uart_line_read.  Times are in any unit (the
 * core uses cluster cycles); only their order and the bit time matter.
 */
#ifndef HEXBOT_UART_LINE_H
#define HEXBOT_UART_LINE_H

#include <stdint.h>

/* entries of one byte: start, 8 data, parity, stop, idle */
#define UART_LINE_BYTE_MAX 12

typedef struct uart_edge_t {
	double t;      /* the level begins here */
	uint8_t level; /* 0 low (a lit IR LED, a start bit), 1 high */
} uart_edge_t;

/* The levels of one byte in format (m162_txrec_t.format) from start on, bit
 * long each, into out (UART_LINE_BYTE_MAX entries); returns how many. */
int uart_line_levels(uart_edge_t *out, uint8_t byte, uint8_t format, double start, double bit);

/* The first byte a receiver with this bit time and format reads of the line
 * wave[0..n): the byte | UART_INPUT_FE when its stop bit reads low, or -1
 * when it finds no start bit.  A receiver that came on (RXEN set, after a
 * reset) at since, after the line's first level, looks for a falling edge
 * at or after it: a line already low there is no start bit (the datasheet:
 * the receiver starts on a high-to-low transition).  since at or before
 * the first level (-1): on all along. */
int uart_line_read(const uart_edge_t *wave, int n, double bit, uint8_t format, double since);

/* What a receiver outside the datasheet's baud range, where nothing is
 * promised, reports of byte when exact sampling read got (uart_line_read's
 * result): a byte that sampling still reads right keeps a framing error (a
 * real receiver's edge detection and 3-sample vote may give it one).  The
 * one rule for a whole byte (m162_usart_resample) and a cut one (ir_medium.c);
 * uart_line.py's out_of_range. */
int uart_line_out_of_range(int got, uint8_t byte, uint8_t format);

#endif
