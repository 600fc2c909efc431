/*
 * m162run.c -- run one or more ELF images on the ATmega162 core without
 * Python: a quick look at what firmware does, and a way to use gdb/valgrind
 * on the core itself.
 *
 *   m162run [-c cycles] [-q quantum] [-t baud-tolerance] [-j threads [-m min]] [-w] a.elf ...
 *
 * Prints every byte each USART sends ("mcu uart start end byte") and every
 * PORTx change ("mcu port cycle value"), then each MCU's state.  -w wires
 * USART0 of image 2k to USART0 of image 2k+1 (a module's comm/control pair).
 * -j runs each quantum on that many threads (the output does not change),
 * each with at least -m MCUs (default CLUSTER_MIN_MCUS_PER_THREAD);
 * `make tsan` builds it with ThreadSanitizer over simavr's own sources.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "../cluster.h"

static void drain(cluster_t *c)
{
	for (int i = 0; i < c->n; i++) {
		m162_t *m = c->mcu[i];
		for (int u = 0; u < M162_NUARTS; u++) {
			m162_usart_t *s = &m->usart[u];
			while (s->take_pos < s->log_len && s->log[s->take_pos].end <= c->cycle) {
				m162_txrec_t *r = &s->log[s->take_pos++];
				printf("%d uart%d %llu %llu 0x%02x %c\n", i, u, (unsigned long long)r->start,
						(unsigned long long)r->end, r->byte,
						r->byte >= 32 && r->byte < 127 ? r->byte : '.');
			}
			s->notified_pos = s->take_pos;
		}
		for (size_t k = 0; k < m->pinlog_len; k++)
			printf("%d port%c %llu 0x%02x\n", i, m->pinlog[k].port,
					(unsigned long long)m->pinlog[k].cycle, m->pinlog[k].value);
		m->pinlog_len = 0;
	}
}

int main(int argc, char **argv)
{
	unsigned long long cycles = 1000000, quantum = 1000;
	/* the simulator takes it from protocol/timing.py BAUD_TOLERANCE */
	double tolerance = 0.045;
	int wire = 0, threads = 1, min_per_thread = CLUSTER_MIN_MCUS_PER_THREAD, opt;
	while ((opt = getopt(argc, argv, "c:q:t:j:m:w")) != -1) {
		switch (opt) {
		case 'c': cycles = strtoull(optarg, NULL, 0); break;
		case 'q': quantum = strtoull(optarg, NULL, 0); break;
		case 't': tolerance = strtod(optarg, NULL); break;
		case 'j': threads = atoi(optarg); break;
		case 'm': min_per_thread = atoi(optarg); break;
		case 'w': wire = 1; break;
		default:
			fprintf(stderr, "usage: %s [-c cycles] [-q quantum] [-t tolerance] [-j threads] "
					"[-m min] [-w] a.elf ...\n", argv[0]);
			return 2;
		}
	}
	if (optind >= argc) {
		fprintf(stderr, "%s: no ELF file given\n", argv[0]);
		return 2;
	}
	cluster_t *c = cluster_new(quantum, tolerance);
	if (cluster_set_threads(c, threads) < 0) {
		fprintf(stderr, "%s: cannot run on %d threads\n", argv[0], threads);
		cluster_free(c);
		return 2;
	}
	c->min_per_thread = min_per_thread > 0 ? min_per_thread : 1;
	for (int i = optind; i < argc; i++) {
		char err[512];
		int idx = cluster_add(c, argv[i], argv[i], "atmega162", err, sizeof err);
		if (idx < 0) {
			fprintf(stderr, "%s\n", err);
			cluster_free(c);
			return 1;
		}
		cluster_watch(c, idx, 0);
		cluster_watch(c, idx, 1);
		if (wire && idx % 2 == 1)
			cluster_connect(c, idx - 1, 0, idx, 0);
	}
	while (cluster_run(c, cycles) < cycles)
		drain(c);
	drain(c);
	for (int i = 0; i < c->n; i++)
		printf("%d state %s %s\n", i, m162_state_name(c->mcu[i]->avr->state),
				c->mcu[i]->last_error);
	cluster_free(c);
	return 0;
}
