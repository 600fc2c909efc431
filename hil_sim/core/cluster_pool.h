/*
 * cluster_pool.h -- worker threads that run the MCUs of one quantum.
 *
 * Within a quantum the MCUs do not touch each other (bytes move only at the
 * boundary, in cluster.c), so any thread may run any MCU: the result is the
 * same whatever thread ran it and in whatever order.  The caller's thread
 * works too; the others are parked between quanta.  MCUs are handed out
 * from a shared counter in small chunks, so a thread the host preempts
 * (the machine is shared) does not hold the others up for long.
 *
 * The pool only ever calls m162_run_until(): nothing in it reaches Python,
 * so it runs with the GIL released (pyavr.c).
 */
#ifndef HEXBOT_CLUSTER_POOL_H
#define HEXBOT_CLUSTER_POOL_H

#include <stdint.h>

#include "m162.h"

typedef struct cluster_pool_t cluster_pool_t;

/* threads >= 2 in all (the caller's included); NULL if a thread could not
 * be started. */
cluster_pool_t *cluster_pool_new(int threads);
void cluster_pool_free(cluster_pool_t *p);
/* Threads of the pool, the caller's included. */
int cluster_pool_threads(const cluster_pool_t *p);
/* Run mcu[0..n-1] until cluster cycle end (cycles after the last
 * boundary) on this many of the pool's threads (the caller's included, at
 * most cluster_pool_threads) -- or on the caller's alone while that has
 * been faster (see cluster_pool.c); returns when all have reached it. */
void cluster_pool_run(cluster_pool_t *p, m162_t **mcu, int n, uint64_t end, int threads,
		uint64_t cycles);

#endif
