/*
 * uart_line.c -- what a UART reads of a serial line's levels (uart_line.h).
 * Each step mirrors hil_sim/uart_line.py (_waveform, _read) so that both
 * languages read the same bytes, ties included: times are built by the same
 * additions in the same order.
 */
#include "uart_line.h"

#include "sim_avr.h"
#include "avr_uart.h"

int uart_line_levels(uart_edge_t *out, uint8_t byte, uint8_t format, double start, double bit)
{
	int db = format & 0x0F, upm = (format >> 4) & 3, stop_bits = format >> 6;
	if (db > 8)
		db = 8; /* 9-bit frames are not modelled */
	int n = 0, ones = 0;
	double t = start;
	out[n++] = (uart_edge_t){ t, 0 };
	t += bit;
	for (int k = 0; k < db; k++) {
		int level = (byte >> k) & 1;
		ones += level;
		out[n++] = (uart_edge_t){ t, (uint8_t)level };
		t += bit;
	}
	if (upm >= 2) { /* even (2) or odd (3) over the data bits */
		out[n++] = (uart_edge_t){ t, (uint8_t)((ones & 1) ^ (upm == 3)) };
		t += bit;
	}
	out[n++] = (uart_edge_t){ t, 1 }; /* stop bits, then idle */
	t += bit * stop_bits;
	out[n++] = (uart_edge_t){ t, 1 };
	return n;
}

/* the level at t: of the last entry that began at or before t (the first
 * entry's before it), idle high from the last entry on */
static int level_at(const uart_edge_t *w, int n, double t)
{
	int lo = 0, hi = n - 1;
	while (lo < hi) {
		int mid = (lo + hi + 1) / 2;
		if (w[mid].t <= t)
			lo = mid;
		else
			hi = mid - 1;
	}
	return t < w[n - 1].t ? w[lo].level : 1;
}

int uart_line_read(const uart_edge_t *w, int n, double bit, uint8_t format, double since)
{
	int db = format & 0x0F, parity = ((format >> 4) & 3) >= 2;
	if (db > 8)
		db = 8;
	int i = 0;
	double t = w[0].t;
	if (since > t) {
		/* came on at since: the first low level that begins at or after
		 * it after a high one, a falling edge */
		while (i < n - 1 && (w[i].t < since || w[i].level != 0 || (i > 0 && w[i - 1].level == 0)))
			i++;
		if (i >= n - 1)
			return -1;
		t = w[i].t;
	}
	for (;;) {
		/* the line low at or after t: the first low entry not over by t */
		while (i < n - 1 && (w[i].level != 0 || w[i + 1].t <= t))
			i++;
		if (i >= n - 1)
			return -1;
		double edge = t > w[i].t ? t : w[i].t;
		if (level_at(w, n, edge + bit / 2) != 0) { /* a glitch, not a start bit */
			t = edge + bit / 2;
			continue;
		}
		int value = 0;
		for (int k = 0; k < db; k++)
			value |= level_at(w, n, edge + bit * (1.5 + k)) << k;
		double stop = edge + bit * (1 + db + parity + 0.5);
		return value | (level_at(w, n, stop) == 0 ? UART_INPUT_FE : 0);
	}
}

int uart_line_out_of_range(int got, uint8_t byte, uint8_t format)
{
	int db = format & 0x0F;
	if (got >= 0 && (got & 0xFF) == (byte & ((1 << (db < 8 ? db : 8)) - 1)))
		got |= UART_INPUT_FE;
	return got;
}
