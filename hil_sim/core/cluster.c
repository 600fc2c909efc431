/*
 * cluster.c -- lock-step scheduler for several simulated MCUs.
 * See cluster.h for the timing rules.
 */
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cluster.h"
#include "ir_medium.h"
#include "cluster_pool.h"
#include "rf12_part.h"

/* simavr's logger is one global pointer: set it once, before any MCU runs
 * (clusters may be made while another one runs without the GIL). */
static pthread_once_t logger_once = PTHREAD_ONCE_INIT;

static void ensure_logger(void)
{
	pthread_once(&logger_once, m162_install_logger);
}

cluster_t *cluster_new(uint64_t quantum, double baud_tolerance)
{
	ensure_logger();
	cluster_t *c = calloc(1, sizeof *c);
	if (!c)
		return NULL;
	c->quantum = quantum ? quantum : 1000;
	c->baud_tolerance = baud_tolerance;
	c->threads = 1;
	c->min_per_thread = CLUSTER_MIN_MCUS_PER_THREAD;
	return c;
}

void cluster_free(cluster_t *c)
{
	if (!c)
		return;
	if (c->pool_pid == getpid()) /* a forked child's copy has no workers to join */
		cluster_pool_free(c->pool);
	for (int i = 0; i < c->n; i++) {
		rf12_t *radio = c->mcu[i]->rf12; /* the MCU's io list points into it */
		ir_port_t *ir = c->mcu[i]->ir;     /* its timer param, likewise */
		m162_free(c->mcu[i]);
		rf12_free(radio);
		ir_free(ir);
	}
	free(c->mcu);
	free(c->ir);
	free(c);
}

int cluster_add(cluster_t *c, const char *elf_path, const char *name, const char *core,
		char *err, size_t errlen)
{
	FILE *f = fopen(elf_path, "rb");
	if (!f) {
		snprintf(err, errlen, "%s: cannot open", elf_path);
		return -1;
	}
	fclose(f);
	m162_t *m = (!core || !strcmp(core, "atmega162")) ? m162_make() : m162_make_stock(core);
	if (!m) {
		snprintf(err, errlen, "unknown MCU core '%s'", core ? core : "");
		return -1;
	}
	if (m162_load_elf(m, elf_path, err, errlen) != 0) {
		m162_free(m);
		return -1;
	}
	if (c->n && m->avr->frequency != c->frequency) {
		snprintf(err, errlen, "%s: runs at %u Hz but this cluster runs at %u Hz",
				elf_path, m->avr->frequency, c->frequency);
		m162_free(m);
		return -1;
	}
	if (c->n == c->cap) {
		int cap = c->cap ? c->cap * 2 : 16;
		m162_t **n = realloc(c->mcu, cap * sizeof *n);
		if (!n) {
			m162_free(m);
			snprintf(err, errlen, "out of memory");
			return -1;
		}
		c->mcu = n;
		c->cap = cap;
	}
	c->frequency = m->avr->frequency;
	snprintf(m->name, sizeof m->name, "%s", name ? name : "");
	/* a late-added MCU starts at the cluster's present time, on the
	 * nominal clock until told otherwise */
	m->avr->cycle = c->cycle;
	m->clock = (m162_clock_t){ c->frequency, c->frequency, c->cycle, c->cycle };
	c->mcu[c->n] = m;
	return c->n++;
}

static void update_keep(m162_usart_t *s)
{
	m162_usart_set_keep_log(s, s->watched || s->peer != NULL || s->ir_sel_port >= 0);
}

void cluster_connect(cluster_t *c, int a, int ua, int b, int ub)
{
	m162_usart_t *sa = &c->mcu[a]->usart[ua];
	m162_usart_t *sb = &c->mcu[b]->usart[ub];
	sa->peer = sb;
	sb->peer = sa;
	sa->wire_pos = sa->log_len;
	sb->wire_pos = sb->log_len;
	update_keep(sa);
	update_keep(sb);
}

void cluster_watch(cluster_t *c, int mcu, int uart)
{
	m162_usart_t *s = &c->mcu[mcu]->usart[uart];
	if (!s->watched) {
		s->watched = 1;
		s->take_pos = s->notified_pos = s->log_len;
	}
	update_keep(s);
}

void cluster_set_clock(cluster_t *c, int mcu, uint32_t hz)
{
	m162_set_clock(c->mcu[mcu], hz, c->cycle);
}

/* Work done between quanta.  Returns 1 if a watched USART or a radio
 * finished a byte nobody has been told about. */
static int boundary(cluster_t *c)
{
	int news = ir_boundary(c); /* IR bytes between comm boards (ir_medium.c) */
	for (int i = 0; i < c->n; i++) {
		m162_t *m = c->mcu[i];
		if (m->woke) { /* a pin Python watches changed (wake_on_pins) */
			m->woke = 0;
			news = 1;
		}
		if (m->rf12 && rf12_news(m->rf12)) { /* the radio medium routes it */
			news = 1;
			m->changed = 1;
		}
		for (int k = 0; k < M162_NUARTS; k++) {
			m162_usart_t *s = &m->usart[k];
			if (!s->keep_log)
				continue;
			if (s->peer) {
				for (; s->wire_pos < s->log_len; s->wire_pos++) {
					m162_txrec_t *r = &s->log[s->wire_pos];
					/* a receiver set to another baud rate reads
					 * what its UART samples; to another frame
					 * format, a framing error */
					uint16_t v = r->byte;
					int ok = m162_usart_frame_ok(s->peer, r, c->baud_tolerance);
					if (!ok) {
						int got = (r->format & 0x3F) == (s->peer->format & 0x3F)
							? m162_usart_resample(s->peer, r) : (r->byte | UART_INPUT_FE);
						if (got < 0)
							continue; /* no start bit where it looked */
						v = (uint16_t)got;
					}
					m162_usart_queue_rx(s->peer, r, v, ok);
				}
			}
			if (s->watched) {
				while (s->notified_pos < s->log_len &&
						s->log[s->notified_pos].end <= c->cycle) {
					s->notified_pos++;
					news = 1;
					m->changed = 1;
				}
			}
			if (s->log_len > 256)
				m162_usart_compact_log(s);
		}
	}
	return news;
}

int cluster_set_threads(cluster_t *c, int threads)
{
	if (threads < 1)
		return -1;
	cluster_pool_t *pool = NULL;
	if (threads > 1 && !(pool = cluster_pool_new(threads)))
		return -1;
	if (c->pool_pid == getpid())
		cluster_pool_free(c->pool);
	c->pool = pool;
	c->pool_pid = getpid();
	c->threads = threads;
	return 0;
}

/* After fork() the workers stayed in the parent, and the pool's lock may
 * have been copied held: leave that pool alone and start a new one. */
static void own_pool(cluster_t *c)
{
	if (!c->pool || c->pool_pid == getpid())
		return;
	c->pool = cluster_pool_new(c->threads); /* NULL: one thread from now on */
	c->pool_pid = getpid();
}

/* Threads for one quantum: as many as asked, but each with at least
 * min_per_thread MCUs -- below that, handing work over costs more than it
 * saves (a quantum of 7 idle modules is ~10 us of work). */
static int quantum_threads(const cluster_t *c)
{
	int threads = c->threads;
	if (c->min_per_thread > 1 && threads > c->n / c->min_per_thread)
		threads = c->n / c->min_per_thread;
	return threads > 1 ? threads : 1;
}

/* Every MCU to cycle end: the MCUs do not interact within a quantum, so
 * one thread or several give the same state. */
static void run_quantum(cluster_t *c, uint64_t end)
{
	int threads = c->pool ? quantum_threads(c) : 1;
	if (threads > 1) {
		cluster_pool_run(c->pool, c->mcu, c->n, end, threads, end - c->cycle);
		return;
	}
	for (int i = 0; i < c->n; i++)
		m162_run_until(c->mcu[i], end);
}

uint64_t cluster_run(cluster_t *c, uint64_t until)
{
	own_pool(c);
	while (c->cycle < until) {
		uint64_t end = c->cycle + c->quantum;
		if (end > until)
			end = until;
		run_quantum(c, end);
		c->cycle = end;
		if (boundary(c))
			break;
	}
	return c->cycle;
}
