/*
 * cluster.h -- several simulated MCUs advanced in lock-step.
 *
 * Time is cut into quanta of Q cycles (default 1000 = 1 ms at 1 MHz).  In
 * each quantum every MCU (in index order, or on several threads) runs until its cycle counter
 * reaches the quantum's end (an instruction may overshoot by a few cycles; a
 * sleeping MCU lands exactly on it).  Only then are bytes moved between
 * MCUs, so the result does not depend on the order MCUs are stepped in, on
 * the host's speed or on threads: the same inputs give the same trace.
 *
 * A byte on a connect_uart() wire is handed to the receiver at the boundary
 * after its first bit went out, due in the middle of its stop bit (where the
 * part raises RXC); the receiver gets it exactly then if that is still in the
 * future, otherwise at once.  A quantum no longer than the shortest start-to-
 * mid-stop time on any wire (the lookahead, e.g. 9.5 bit times at 4800 baud
 * = 1,979 cycles at 1 MHz) makes every delivery exact.  A receiver whose
 * baud rate differs by more than the tolerance (protocol/timing.py
 * BAUD_TOLERANCE, given to cluster_new) or whose frame format differs gets
 * the byte with a framing error.
 *
 * Time is counted in cycles of the nominal clock (the ELF's frequency); an
 * MCU may run on its own clock (m162_set_clock), and everything the cluster
 * reports (byte and pin-log cycles) is converted to cluster cycles.
 *
 * The MCUs of a quantum may run on several threads (cluster_set_threads,
 * cluster_pool.h): they share nothing until the boundary, which runs on the
 * caller's thread alone, so the trace is the same with 1 or N threads.
 *
 * An MCU may carry an RF12 radio (rf12_part.h); run() returns at the first
 * boundary after one of its bytes left the air, for Python's medium
 * (hil_sim/radio.py) to route it.
 */
#ifndef HEXBOT_CLUSTER_H
#define HEXBOT_CLUSTER_H

#include <stddef.h>
#include <stdint.h>

#include "m162.h"

typedef struct cluster_t {
	uint64_t quantum;
	uint64_t cycle;
	double baud_tolerance;
	uint32_t frequency; /* shared by all MCUs; 0 until the first is added */
	m162_t **mcu;
	int n, cap;
	struct ir_port_t **ir; /* MCUs on the IR medium (ir_medium.c), in index order */
	int n_ir;
	int threads;                  /* that run a quantum, the caller's included */
	int min_per_thread;           /* fewer threads if one would get fewer MCUs */
	struct cluster_pool_t *pool; /* NULL with one thread */
	int pool_pid;                 /* process whose threads the pool holds (fork) */
} cluster_t;

/* A quantum uses at most n / this threads: 32 MCUs of idle firmware are
 * about 20 us of work (0.65 us each, bench sim at 7 and 50 modules), the
 * order of what waking a parked thread costs. */
#define CLUSTER_MIN_MCUS_PER_THREAD 32

cluster_t *cluster_new(uint64_t quantum, double baud_tolerance);
void cluster_free(cluster_t *c);
/* core: "atmega162" (ours) or the name of a stock simavr core.
 * Returns the index, or -1 with a message in err. */
int cluster_add(cluster_t *c, const char *elf_path, const char *name, const char *core,
		char *err, size_t errlen);
void cluster_connect(cluster_t *c, int a, int ua, int b, int ub);
void cluster_watch(cluster_t *c, int mcu, int uart);
/* Set MCU mcu's clock to hz from now on (the nominal clock: cluster->frequency). */
void cluster_set_clock(cluster_t *c, int mcu, uint32_t hz);
/* Run quanta on this many threads (>= 1; more than MCUs is allowed, the
 * spare ones find nothing to do).  A quantum uses fewer when a thread would
 * get fewer than c->min_per_thread MCUs (default
 * CLUSTER_MIN_MCUS_PER_THREAD; 1 always uses them all).  Returns -1 if
 * threads < 1 or a thread could not be started (the old setting stays). */
int cluster_set_threads(cluster_t *c, int threads);
/* Advance to until (a multiple of nothing in particular); returns the cycle
 * reached, earlier if a watched USART finished a byte. */
uint64_t cluster_run(cluster_t *c, uint64_t until);

#endif
