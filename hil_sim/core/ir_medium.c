/*
 * ir_medium.c -- the IR medium between communication boards (ir_medium.h).
 */
#include <stdlib.h>
#include <string.h>

#include "ir_medium.h"
#include "grow.h"
#include "uart_line.h"

static int selector_y(const ir_port_t *p)
{
	uint8_t v = p->m->avr->data[m162_port_regs[p->sel_port][2]];
	int a = v >> p->sel_bits[0] & 1, b = v >> p->sel_bits[1] & 1, cc = v >> p->sel_bits[2] & 1;
	return 4 * cc + 2 * b + a;
}

static int selector_y_of(const ir_port_t *p, uint8_t v)
{
	return 4 * (v >> p->sel_bits[2] & 1) + 2 * (v >> p->sel_bits[1] & 1) + (v >> p->sel_bits[0] & 1);
}

/* xorshift64*: a receiver's own sequence, so the draws do not depend on
 * the order receivers run in */
static uint8_t next_garbage(ir_port_t *p)
{
	uint64_t x = p->rng;
	x ^= x >> 12;
	x ^= x << 25;
	x ^= x >> 27;
	p->rng = x;
	return (uint8_t)((x * 0x2545F4914F6CDD1DULL) >> 56);
}

static void log_event(ir_port_t *p, int kind, const ir_air_t *a, const int *others, int n)
{
	if (GROW(p->events, p->n_events, p->cap_events, 32) < 0)
		return;
	ir_event_t *e = &p->events[p->n_events++];
	*e = (ir_event_t){ .end = a->end, .seq = p->seq++, .kind = kind, .sender = a->sender,
		.receiver = p->index, .byte = a->byte, .n_others = n };
	memcpy(e->others, others, (size_t)n * sizeof *others);
}

/* where a byte's stop bit begins (ir_part_stop, one formula) */
static double stop_of(uint64_t start, double bit, uint8_t format)
{
	ir_part_t part = { .start = (double)start, .bit = bit, .format = format };
	return ir_part_stop(&part);
}

/* ---------------------------------------------------------------- */
/* selector history: who saw which part of a byte */

static void note(ir_port_t *p, uint64_t cycle, int y)
{
	if (GROW(p->fresh, p->n_fresh, p->cap_fresh, 16) == 0)
		p->fresh[p->n_fresh++] = (ir_mark_t){ cycle, y };
}

void ir_note_port(ir_port_t *p, int port, uint8_t value, uint64_t cycle)
{
	if (port != p->sel_port)
		return;
	int y = selector_y_of(p, value);
	if (y != p->y_now) {
		p->y_now = y;
		note(p, cycle, y);
	}
}

void ir_note_reset(ir_port_t *p, uint64_t cycle)
{
	note(p, cycle, IR_MARK_RESET);
}

void ir_note_rx(ir_port_t *p, const m162_usart_t *s, uint64_t cycle, int on)
{
	if (s != p->s)
		return;
	if (GROW(p->rx, p->n_rx, p->cap_rx, 8) == 0)
		p->rx[p->n_rx++] = (m162_rxmark_t){ cycle, on };
}

/* Whether p's receiver is on at horizon h by its own changes before h, and
 * since when (the cycle it came on last; ir_medium.h). */
static int rx_on_at(const ir_port_t *p, double h, double *since)
{
	int on = p->rx_before_on;
	uint64_t from = p->rx_before_since;
	for (size_t k = 0; k < p->n_rx && (double)p->rx[k].cycle < h; k++) {
		if (p->rx[k].on && !on)
			from = p->rx[k].cycle;
		on = p->rx[k].on;
	}
	*since = (double)from;
	return on;
}

/* At a boundary: changes older than any byte can reach back to fold into
 * the state before. */
static void prune_rx(ir_port_t *p, uint64_t now, uint64_t quantum)
{
	uint64_t keep = 2 * p->longest + quantum;
	size_t drop = 0;
	while (drop < p->n_rx && p->rx[drop].cycle + keep < now) {
		if (p->rx[drop].on && !p->rx_before_on)
			p->rx_before_since = p->rx[drop].cycle;
		p->rx_before_on = p->rx[drop].on;
		drop++;
	}
	memmove(p->rx, p->rx + drop, (p->n_rx - drop) * sizeof *p->rx);
	p->n_rx -= drop;
}

/* The middle of a's stop bit by its sender's bit time: p's own on/off
 * changes count before it (rx_on_at) */
static double horizon(const ir_air_t *a)
{
	return a->stop + a->bit / 2;
}

/* At a boundary: fresh marks become readable by every MCU; marks older than
 * any byte on the air can reach back to are folded into y_before. */
static void publish(ir_port_t *p, uint64_t now, uint64_t quantum)
{
	if (!p->n_fresh && !p->n_marks)
		return; /* the usual boundary: a selector moves a few times a second */
	uint64_t keep = 2 * p->longest + quantum;
	size_t drop = 0;
	while (drop < p->n_marks && p->marks[drop].cycle + keep < now) {
		if (p->marks[drop].y != IR_MARK_RESET)
			p->y_before = p->marks[drop].y;
		drop++;
	}
	memmove(p->marks, p->marks + drop, (p->n_marks - drop) * sizeof *p->marks);
	p->n_marks -= drop;
	for (size_t k = 0; k < p->n_fresh; k++)
		if (GROW(p->marks, p->n_marks, p->cap_marks, 16) == 0)
			p->marks[p->n_marks++] = p->fresh[k];
	p->n_fresh = 0;
}

/* the port's selector index at cycle t, by its own history (its own run) */
static int y_at(const ir_port_t *p, uint64_t t)
{
	int y = p->y_before;
	for (size_t k = 0; k < p->n_marks + p->n_fresh; k++) {
		const ir_mark_t *m = k < p->n_marks ? &p->marks[k] : &p->fresh[k - p->n_marks];
		if (m->cycle > t)
			break;
		if (m->y != IR_MARK_RESET)
			y = m->y;
	}
	return y;
}

/* Parts of [start, end) where a selector that was on y at start, and moved
 * at marks a then b, is on keep (ir_line.py spans_where). */
static int spans_where(ir_span_t *out, uint64_t start, double end, int y, int keep,
		const ir_mark_t *a, size_t na, const ir_mark_t *b, size_t nb)
{
	int n = 0, on = y == keep;
	uint64_t since = start;
	for (size_t k = 0; k < na + nb; k++) {
		const ir_mark_t *m = k < na ? &a[k] : &b[k - na];
		if (m->y == IR_MARK_RESET || m->cycle <= start || (double)m->cycle >= end)
			continue;
		if (on && m->y != keep) {
			out[n++] = (ir_span_t){ (double)since, (double)m->cycle };
			on = 0;
			if (n == IR_MAX_SPANS)
				return n;
		} else if (!on && m->y == keep) {
			since = m->cycle;
			on = 1;
		}
	}
	if (on && n < IR_MAX_SPANS)
		out[n++] = (ir_span_t){ (double)since, end };
	return n;
}

/* The spans in which the receiver p sees byte a up to its stop bit (at
 * stop: from there on its line is high either way, ir_line.h): the sender
 * still on the byte's channel and not reset since (its published marks,
 * all of them up to stop: settled()), p on the facing index (its own
 * marks).  0: it saw nothing of it. */
static int seen_spans(const ir_port_t *p, const ir_air_t *a, double stop, ir_span_t *out)
{
	ir_span_t sent[IR_MAX_SPANS], heard[IR_MAX_SPANS];
	int ns = 1;
	sent[0] = (ir_span_t){ (double)a->start, stop };
	const ir_port_t *f = a->from;
	if (f) {
		double end = stop; /* the first reset in (start, stop] */
		for (size_t k = 0; k < f->n_marks; k++)
			if (f->marks[k].y == IR_MARK_RESET && f->marks[k].cycle > a->start &&
					(double)f->marks[k].cycle <= end) {
				end = (double)f->marks[k].cycle;
				break;
			}
		ns = spans_where(sent, a->start, end, a->sent_y, a->sent_y, f->marks, f->n_marks,
				NULL, 0);
	}
	int nh = spans_where(heard, a->start, stop, y_at(p, a->start), a->need_y, p->marks,
			p->n_marks, p->fresh, p->n_fresh);
	return ir_spans_intersect(out, sent, ns, heard, nh);
}

/* Every move and reset of a's sender before its stop bit is published
 * (the last boundary is at or after it): a can be read now.  With a
 * quantum longer than half a bit the middle of the stop bit can come
 * before that boundary; the byte then waits for it (ir_boundary). */
static int settled(const ir_port_t *p, const ir_air_t *a)
{
	return !a->from || (double)p->published >= a->stop;
}

/* ---------------------------------------------------------------- */
/* receiving */

static int has_sender(const ir_port_t *p, int sender)
{
	for (int i = 0; i < p->last.n; i++)
		if (p->last.senders[i] == sender)
			return 1;
	return 0;
}

/* The byte reaches the receiver's antenna now (middle of its stop bit). */
static void arrive(ir_port_t *p, const ir_air_t *a)
{
	ir_part_t part = { (double)a->start, (double)a->end, a->bit, a->byte,
		a->format, 0, { { 0, 0 } } };
	part.n_spans = seen_spans(p, a, a->stop, part.spans);
	if (!part.n_spans)
		return; /* looking elsewhere: lost in the air, as in ir_bus.py */
	uint8_t value = a->byte;
	int fe = 0;
	double since;
	int on = rx_on_at(p, horizon(a), &since);
	/* it came on within the byte: it lost what it had and looks for a
	 * falling edge from there (ir_line_read) */
	int late = on && since > (double)a->start;
	if (!on)
		since = -1.0; /* dropped below; read as if on, for a collision to come */
	double own = m162_bit_time(p->m, p->s->bit_cycles);
	m162_txrec_t rec = { a->start, a->due, a->end, a->byte, a->format, a->bit };
	int same_word = (rec.format & 0x3F) == (p->s->format & 0x3F);
	int frame_ok = m162_usart_frame_ok(p->s, &rec, p->tolerance);
	if (!frame_ok)
		log_event(p, IR_EV_GARBLED, a, NULL, 0);
	if ((!ir_part_whole(&part) || late) && same_word) {
		/* cut: what the receiver's UART samples of the part it saw, from
		 * where it came on, by the rule of a whole byte at its rate
		 * (m162_usart_resample) */
		int got = ir_line_read(&part, 1, own, p->s->format, since);
		if (!frame_ok)
			got = uart_line_out_of_range(got, a->byte, a->format);
		if (got < 0)
			return; /* no start bit where it looked: nothing */
		value = (uint8_t)got;
		fe = (got & UART_INPUT_FE) != 0;
	} else if (!frame_ok) {
		if (same_word) {
			/* another baud rate: what the receiver's UART samples */
			int got = m162_usart_resample(p->s, &rec);
			if (got < 0)
				return; /* no start bit where it looked: nothing */
			value = (uint8_t)got;
			fe = (got & UART_INPUT_FE) != 0;
		} else { /* another word format: garbage from the seeded generator */
			value = next_garbage(p);
			fe = 1;
		}
	}
	if (p->last.valid && p->last.start < a->end && a->start < p->last.end &&
			!has_sender(p, a->sender)) {
		/* the receiver learns of the collision as the second byte ends:
		 * what it samples of the AND of both lines, broken */
		log_event(p, IR_EV_COLLISION, a, p->last.senders, p->last.n);
		if (a->start < p->last.start)
			p->last.start = a->start;
		if (a->end > p->last.end)
			p->last.end = a->end;
		if (p->last.n < IR_MAX_SENDERS) {
			p->last.parts[p->last.n] = part;
			p->last.senders[p->last.n++] = a->sender;
		}
		/* started together, whole, heard from the start: the AND of the values */
		int together = since <= part.start;
		for (int k = 0; k < p->last.n; k++)
			together &= p->last.parts[k].start == part.start &&
				ir_part_whole(&p->last.parts[k]);
		if (together) {
			p->last.value &= value;
		} else {
			int got = ir_line_read(p->last.parts, p->last.n, own, p->s->format, since);
			if (got >= 0)
				p->last.value = (uint8_t)got;
		}
		p->last.fe = 1;
	} else {
		p->last.valid = 1;
		p->last.start = a->start;
		p->last.end = a->end;
		p->last.senders[0] = a->sender;
		p->last.parts[0] = part;
		p->last.n = 1;
		p->last.value = value;
		p->last.fe = fe;
	}
	uint16_t v = p->last.value | (p->last.fe ? UART_INPUT_FE : 0);
	if (!on) /* off at the byte's horizon: lost, as m162_usart_put drops it */
		p->s->rx_dropped++;
	if (!on || !m162_usart_put(p->s, v))
		log_event(p, IR_EV_DROPPED, a, NULL, 0);
}

static void pop_due(ir_port_t *p, uint64_t local_now)
{
	int k = 0;
	while (k < p->inbox_len && p->inbox[k].due_local <= local_now && settled(p, &p->inbox[k]))
		k++;
	/* copy first: arrive() does not touch the inbox, but keep it simple */
	for (int i = 0; i < k; i++)
		arrive(p, &p->inbox[i]);
	memmove(p->inbox, p->inbox + k, (size_t)(p->inbox_len - k) * sizeof *p->inbox);
	p->inbox_len -= k;
}

static avr_cycle_count_t due_timer(avr_t *avr, avr_cycle_count_t when, void *param)
{
	ir_port_t *p = (ir_port_t *)param;
	(void)avr;
	pop_due(p, when);
	/* a byte due but not settled waits for the boundary (ir_boundary) */
	return p->inbox_len && p->inbox[0].due_local > when ? p->inbox[0].due_local : 0;
}

static void arm(ir_port_t *p)
{
	avr_t *avr = p->m->avr;
	avr_cycle_timer_cancel(avr, due_timer, p);
	if (p->inbox_len) {
		uint64_t due = p->inbox[0].due_local;
		avr_cycle_timer_register(avr, due > avr->cycle ? due - avr->cycle : 0, due_timer, p);
	}
}

static int alive(const ir_port_t *p)
{
	int st = p->m->avr->state;
	return st == cpu_Running || st == cpu_Sleeping;
}

/* Called at a boundary or between runs, never while p's MCU runs. */
static void enqueue(ir_port_t *p, ir_air_t a)
{
	avr_t *avr = p->m->avr;
	if (a.end - a.start > p->longest)
		p->longest = a.end - a.start;
	a.due_local = m162_to_local(p->m, a.due);
	/* not before the receiver's run has passed every cycle before the
	 * horizon: its own changes there are then all noted (an instruction of
	 * the local cycle of the last one runs before a timer of the next) */
	double h = horizon(&a);
	uint64_t last = (double)(uint64_t)h == h ? (uint64_t)h - 1 : (uint64_t)h;
	uint64_t need = m162_to_local(p->m, last) + 1;
	if (a.due_local < need)
		a.due_local = need;
	if (a.due_local <= avr->cycle && p->inbox_len == 0 && settled(p, &a)) {
		arrive(p, &a); /* the quantum was longer than the byte: at once */
		return;
	}
	if (p->inbox_len == IR_INBOX) {
		p->overflow++;
		return;
	}
	if (a.due_local < avr->cycle)
		a.due_local = avr->cycle;
	int k = p->inbox_len;
	while (k > 0 && p->inbox[k - 1].due_local > a.due_local)
		k--;
	memmove(p->inbox + k + 1, p->inbox + k, (size_t)(p->inbox_len - k) * sizeof *p->inbox);
	p->inbox[k] = a;
	p->inbox_len++;
	if (k == 0)
		arm(p);
}

static void push_pc(ir_port_t *p, const m162_txrec_t *r)
{
	if (GROW(p->to_pc, p->n_pc, p->cap_pc, 16) < 0)
		return;
	p->to_pc[p->n_pc++] = (ir_pcbyte_t){ r->start, r->end, r->byte };
}

/* At a boundary after r started, so p's marks up to it are published: the
 * side is the selector at the start bit, a write on that very cycle
 * included (docs/simulator.md, "the sender's channel"). */
static void route(cluster_t *c, ir_port_t *p, const m162_txrec_t *r)
{
	int y = y_at(p, r->start);
	const ir_route_t *rt = &p->routes[y];
	if (r->end - r->start > p->longest)
		p->longest = r->end - r->start;
	if (rt->kind == IR_ROUTE_PC) {
		push_pc(p, r);
	} else if (rt->kind == IR_ROUTE_MODULE && rt->target >= 0 && rt->target < c->n &&
			c->mcu[rt->target]->ir) {
		enqueue(c->mcu[rt->target]->ir, (ir_air_t){ .start = r->start, .due = r->mid_stop,
			.end = r->end, .sender = p->index, .from = p, .byte = r->byte,
			.format = r->format, .need_y = (uint8_t)rt->need_y, .sent_y = (int8_t)y,
			.bit = r->bit, .stop = stop_of(r->start, r->bit, r->format) });
	}
}

int ir_attach(cluster_t *c, int mcu, int uart, int sel_port, const uint8_t sel_bits[3])
{
	m162_t *m = c->mcu[mcu];
	ir_port_t *p = m->ir;
	if (!p) {
		ir_port_t **list = realloc(c->ir, (size_t)(c->n_ir + 1) * sizeof *list);
		if (!list)
			return -1;
		c->ir = list;
		p = calloc(1, sizeof *p);
		if (!p)
			return -1;
		m->ir = p;
		/* keep the list in index order: routing order decides ties */
		int k = c->n_ir++;
		while (k > 0 && c->ir[k - 1]->index > mcu) {
			c->ir[k] = c->ir[k - 1];
			k--;
		}
		c->ir[k] = p;
		p->index = mcu;
	}
	p->m = m;
	p->index = mcu;
	p->s = &m->usart[uart];
	p->sel_port = sel_port;
	memcpy(p->sel_bits, sel_bits, 3);
	p->tolerance = c->baud_tolerance;
	p->centre_y = -1;
	p->rng = 0x9E3779B97F4A7C15ULL ^ (uint64_t)(mcu + 1);
	p->y_before = p->y_now = selector_y(p);
	p->n_fresh = p->n_marks = 0;
	p->rx_before_on = p->s->rx_on;
	p->rx_before_since = 0;
	p->n_rx = 0;
	p->s->ir_sel_port = sel_port;
	p->s->ir_pos = p->s->log_len;
	m162_usart_set_keep_log(p->s, 1);
	return 0;
}

void ir_set_routes(cluster_t *c, int mcu, const ir_route_t routes[8])
{
	ir_port_t *p = c->mcu[mcu]->ir;
	memcpy(p->routes, routes, sizeof p->routes);
	p->centre_y = -1;
	for (int y = 0; y < 8; y++)
		if (routes[y].kind == IR_ROUTE_PC)
			p->centre_y = y;
}

void ir_set_seed(cluster_t *c, uint64_t seed)
{
	for (int k = 0; k < c->n_ir; k++) {
		ir_port_t *p = c->ir[k];
		int i = p->index;
		/* splitmix64 of (seed, index): never 0, different per receiver */
		uint64_t z = seed + 0x9E3779B97F4A7C15ULL * (uint64_t)(i + 1);
		z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
		z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
		z ^= z >> 31;
		p->rng = z ? z : 1;
	}
}

void ir_send_from_pc(cluster_t *c, uint64_t start, uint64_t end, uint8_t byte, uint8_t format)
{
	/* The PC's bit time: its byte's length over its bits, not rounded (as
	 * the Python medium's AirByte.bit); it is sent with one stop bit, whose
	 * middle is half a bit before the end. */
	int bits = 1 + (format & 0x0F) + (((format >> 4) & 3) >= 2) + (format >> 6);
	double bit = (double)(end - start) / bits;
	uint64_t mid = end - (uint64_t)(bit / 2);
	for (int i = 0; i < c->n_ir; i++) {
		ir_port_t *p = c->ir[i];
		if (p->centre_y < 0)
			continue;
		enqueue(p, (ir_air_t){ .start = start, .due = mid, .end = end, .sender = IR_PC,
			.byte = byte, .format = format, .need_y = (uint8_t)p->centre_y,
			.bit = bit, .stop = stop_of(start, bit, format) });
	}
}

int ir_boundary(cluster_t *c)
{
	int news = 0;
	for (int i = 0; i < c->n_ir; i++) {
		c->ir[i]->published = c->cycle;
		publish(c->ir[i], c->cycle, c->quantum);
		if (c->ir[i]->n_rx)
			prune_rx(c->ir[i], c->cycle, c->quantum);
	}
	for (int i = 0; i < c->n_ir; i++) {
		ir_port_t *p = c->ir[i];
		m162_usart_t *s = p->s;
		for (; s->ir_pos < s->log_len; s->ir_pos++)
			route(c, p, &s->log[s->ir_pos]);
	}
	for (int i = 0; i < c->n_ir; i++) {
		ir_port_t *p = c->ir[i];
		if (p->inbox_len) {
			avr_t *avr = p->m->avr;
			/* crashed or done: its USART still fills up; else bytes that
			 * waited for this boundary (settled) */
			if (!alive(p) || p->inbox[0].due_local <= avr->cycle)
				pop_due(p, avr->cycle);
			if (p->inbox_len && alive(p) && !avr_cycle_timer_status(avr, due_timer, p))
				arm(p); /* a reset cleared the MCU's timers, or it waited */
		}
		while (p->pc_notified < p->n_pc && p->to_pc[p->pc_notified].end <= c->cycle) {
			p->pc_notified++;
			news = 1;
		}
	}
	return news;
}

size_t ir_take_pc(ir_port_t *p, uint64_t now, ir_pcbyte_t *out, size_t max)
{
	size_t k = 0;
	while (k < p->n_pc && k < max && p->to_pc[k].end <= now) {
		out[k] = p->to_pc[k];
		k++;
	}
	memmove(p->to_pc, p->to_pc + k, (p->n_pc - k) * sizeof *p->to_pc);
	p->n_pc -= k;
	p->pc_notified = p->pc_notified > k ? p->pc_notified - k : 0;
	return k;
}

void ir_free(ir_port_t *p)
{
	if (!p)
		return;
	free(p->events);
	free(p->to_pc);
	free(p->fresh);
	free(p->marks);
	free(p->rx);
	free(p);
}
