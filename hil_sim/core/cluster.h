/*
 * cluster.h -- several simulated MCUs advanced in lock-step.
 *
 * Time is cut into quanta of Q cycles (default 1000 = 1 ms at 1 MHz).  In
 * each quantum every MCU, in index order, runs until its cycle counter
 * reaches the quantum's end (an instruction may overshoot by a few cycles; a
 * sleeping MCU lands exactly on it).  Only then are bytes moved between
 * MCUs, so the result does not depend on the order MCUs are stepped in, on
 * the host's speed or on threads: the same inputs give the same trace.
 *
 * A byte on a connect_uart() wire is handed to the receiver at the boundary
 * after its first bit went out, due at the cycle its stop bit ends; the
 * receiver gets it exactly then if that is still in the future (frames
 * longer than a quantum, e.g. 4800 baud at 1 MHz with Q = 1000), otherwise
 * at once.  A receiver whose baud rate differs by more than 4.5 % or whose
 * frame format differs gets the byte with a framing error.
 */
#ifndef HEXBOT_CLUSTER_H
#define HEXBOT_CLUSTER_H

#include <stddef.h>
#include <stdint.h>

#include "m162.h"

typedef struct cluster_t {
	uint64_t quantum;
	uint64_t cycle;
	uint32_t frequency; /* shared by all MCUs; 0 until the first is added */
	m162_t **mcu;
	int n, cap;
} cluster_t;

cluster_t *cluster_new(uint64_t quantum);
void cluster_free(cluster_t *c);
/* core: "atmega162" (ours) or the name of a stock simavr core.
 * Returns the index, or -1 with a message in err. */
int cluster_add(cluster_t *c, const char *elf_path, const char *name, const char *core,
		char *err, size_t errlen);
void cluster_connect(cluster_t *c, int a, int ua, int b, int ub);
void cluster_watch(cluster_t *c, int mcu, int uart);
/* Advance to until (a multiple of nothing in particular); returns the cycle
 * reached, earlier if a watched USART finished a byte. */
uint64_t cluster_run(cluster_t *c, uint64_t until);

#endif
