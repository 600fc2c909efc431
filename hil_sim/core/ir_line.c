/*
 * ir_line.c -- the IR line of cut and colliding bytes (ir_line.h), step by
 * step as hil_sim/ir_line.py builds it.
 */
#include <stdlib.h>

#include "ir_line.h"
#include "uart_line.h"

#define IR_LINE_PARTS 8 /* ir_medium.h IR_MAX_SENDERS */
#define IR_LINE_TIMES (IR_LINE_PARTS * (UART_LINE_BYTE_MAX + 2 * IR_MAX_SPANS))

double ir_part_stop(const ir_part_t *p)
{
	int db = p->format & 0x0F, parity = ((p->format >> 4) & 3) >= 2;
	if (db > 8)
		db = 8;
	return p->start + (1 + db + parity) * p->bit;
}

int ir_part_whole(const ir_part_t *p)
{
	return p->n_spans == 1 && p->spans[0].from == p->start &&
		p->spans[0].to == ir_part_stop(p);
}

int ir_spans_intersect(ir_span_t *out, const ir_span_t *a, int na, const ir_span_t *b, int nb)
{
	/* both lists are ordered and disjoint: so is the result, in order */
	int n = 0;
	for (int i = 0; i < na; i++)
		for (int j = 0; j < nb && n < IR_MAX_SPANS; j++) {
			double lo = a[i].from > b[j].from ? a[i].from : b[j].from;
			double hi = a[i].to < b[j].to ? a[i].to : b[j].to;
			if (lo < hi)
				out[n++] = (ir_span_t){ lo, hi };
		}
	return n;
}

/* the part's level at t: its byte's where the receiver sees it, else high */
static int part_level(const ir_part_t *p, const uart_edge_t *w, int n, double t)
{
	int seen = 0;
	for (int k = 0; k < p->n_spans; k++)
		seen |= p->spans[k].from <= t && t < p->spans[k].to;
	if (!seen)
		return 1;
	int at = 1;
	for (int k = 0; k < n && w[k].t <= t; k++)
		at = w[k].level;
	return t < w[n - 1].t && t >= w[0].t ? at : 1;
}

static int by_time(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

int ir_line_read(const ir_part_t *parts, int n, double bit, uint8_t format, double since)
{
	uart_edge_t waves[IR_LINE_PARTS][UART_LINE_BYTE_MAX];
	int lens[IR_LINE_PARTS];
	double times[IR_LINE_TIMES];
	int nt = 0;
	if (n > IR_LINE_PARTS)
		n = IR_LINE_PARTS;
	for (int i = 0; i < n; i++) {
		const ir_part_t *p = &parts[i];
		lens[i] = uart_line_levels(waves[i], p->byte, p->format, p->start, p->bit);
		for (int k = 0; k < lens[i]; k++)
			times[nt++] = waves[i][k].t;
		for (int k = 0; k < p->n_spans; k++) {
			times[nt++] = p->spans[k].from;
			times[nt++] = p->spans[k].to;
		}
	}
	if (nt == 0)
		return -1;
	qsort(times, (size_t)nt, sizeof *times, by_time);
	/* the AND of the parts at every time one of them may change */
	uart_edge_t line[IR_LINE_TIMES + 1];
	int nl = 0;
	for (int k = 0; k < nt; k++) {
		if (k > 0 && times[k] == times[k - 1])
			continue;
		int level = 1;
		for (int i = 0; i < n; i++)
			level &= part_level(&parts[i], waves[i], lens[i], times[k]);
		if (nl == 0 || line[nl - 1].level != level)
			line[nl++] = (uart_edge_t){ times[k], (uint8_t)level };
	}
	if (line[nl - 1].level != 1)
		line[nl++] = (uart_edge_t){ times[nt - 1], 1 };
	return uart_line_read(line, nl, bit, format, since);
}
