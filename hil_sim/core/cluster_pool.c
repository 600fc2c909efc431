/*
 * cluster_pool.c -- worker threads for one quantum; see cluster_pool.h.
 *
 * One 64-bit ticket holds the quantum's generation (high half) and the next
 * MCU to hand out (low half).  A thread claims a chunk by a compare-and-swap
 * that succeeds only while the generation is the one it woke for and MCUs
 * are left, so a worker that wakes late finds nothing and claims nothing:
 * the caller waits for the MCUs to be done, never for a wake-up.  The job
 * (mcu, n, end) is written before the ticket of its generation and stays
 * until all n MCUs are counted done, so a claimed chunk always sees its own
 * generation's job.
 *
 * Waits spin a little first (within one run() the next quantum follows in
 * microseconds), then sleep on a condition variable, so parked threads cost
 * nothing while Python works between two runs.  The spin is short: on a
 * loaded machine a spinning worker takes CPU from the thread it waits for
 * (2,000 polls cost 15 % at 50 modules against 200 or none, measured with
 * m162run on this shared 2-core machine).
 */
#include <pthread.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <time.h>

#include "cluster_pool.h"

#ifndef CHUNK
#define CHUNK 4          /* MCUs claimed at a time */
#endif
#ifndef SPIN_ROUNDS
#define SPIN_ROUNDS 200 /* polls before sleeping (a few microseconds) */
#endif

struct worker_t {
	struct cluster_pool_t *pool;
	int index; /* 0.. workers-1 */
};

struct cluster_pool_t {
	int workers; /* threads besides the caller's */
	pthread_t *thread;
	struct worker_t *self;
	pthread_mutex_t lock;
	pthread_cond_t start, done;
	atomic_uint_fast64_t ticket; /* generation << 32 | next MCU */
	atomic_int completed;        /* MCUs of this generation done */
	atomic_int stop;
	/* the job of the present generation; n is atomic because a worker that
	 * woke late reads it before its claim fails */
	m162_t **mcu;
	atomic_int n;
	uint64_t end;
	atomic_int helpers; /* workers 0..helpers-1 take part in this generation */
	/* the race between one thread and the pool (see pick_mode) */
	int mode;            /* SOLO or SHARED for this phase */
	int phase;           /* TRY_SHARED, TRY_SOLO, KEEP */
	unsigned phase_left; /* quanta left in it */
	unsigned keep;       /* quanta of the next KEEP phase */
	uint64_t tried_ns[2], tried_cycles[2];
};

/* Whether the pool beats one thread depends on whether the host gives the
 * workers cores of their own, which changes while we run: with Linux's
 * autogroup scheduling another busy session leaves this process one core
 * in all, however many threads it has, and then the threads take turns
 * and wait for each other (255 idle modules ran 37 % slower on 2 threads
 * than on 1).  So the two race: a few quanta on the pool, a few on one
 * thread, then the faster (wall time per cycle) for a longer stretch, and
 * again; each win of one thread doubles that stretch (up to KEEP_MAX), as
 * a trial of the pool on a busy host costs up to 3x.  Which thread runs
 * an MCU never changes the trace. */
enum { SOLO, SHARED };
enum { TRY_SHARED, TRY_SOLO, KEEP };
#define TRY_QUANTA 32
#define KEEP_MIN 512   /* after the pool won */
#define KEEP_MAX 8192  /* one thread keeps winning: try the pool less often */

static inline uint32_t generation_of(uint64_t ticket)
{
	return (uint32_t)(ticket >> 32);
}

static inline void relax(void)
{
#if defined(__x86_64__) || defined(__i386__)
	__builtin_ia32_pause();
#endif
}

/* Claim and run chunks of generation gen until none is left. */
static void run_share(cluster_pool_t *p, uint32_t gen)
{
	uint64_t t = atomic_load(&p->ticket);
	for (;;) {
		int n = atomic_load_explicit(&p->n, memory_order_relaxed);
		if (generation_of(t) != gen || (uint32_t)t >= (uint32_t)n)
			return;
		if (!atomic_compare_exchange_weak(&p->ticket, &t, t + CHUNK))
			continue; /* t now holds the fresh ticket */
		/* claimed: the job is this generation's until the chunk is counted */
		n = atomic_load_explicit(&p->n, memory_order_relaxed);
		int i = (int)(uint32_t)t, stop = i + CHUNK < n ? i + CHUNK : n;
		for (int k = i; k < stop; k++)
			m162_run_until(p->mcu[k], p->end);
		if (atomic_fetch_add(&p->completed, stop - i) + (stop - i) == n) {
			pthread_mutex_lock(&p->lock);
			pthread_cond_signal(&p->done);
			pthread_mutex_unlock(&p->lock);
		}
		t = atomic_load(&p->ticket);
	}
}

static void *worker(void *arg)
{
	struct worker_t *w = arg;
	cluster_pool_t *p = w->pool;
	uint32_t seen = generation_of(atomic_load(&p->ticket));
	for (;;) {
		for (int k = 0; k < SPIN_ROUNDS && generation_of(atomic_load(&p->ticket)) == seen; k++)
			relax();
		if (generation_of(atomic_load(&p->ticket)) == seen) {
			pthread_mutex_lock(&p->lock);
			while (generation_of(atomic_load(&p->ticket)) == seen && !atomic_load(&p->stop))
				pthread_cond_wait(&p->start, &p->lock);
			pthread_mutex_unlock(&p->lock);
		}
		if (atomic_load(&p->stop))
			return NULL;
		seen = generation_of(atomic_load(&p->ticket));
		if (w->index < atomic_load(&p->helpers))
			run_share(p, seen);
	}
}

cluster_pool_t *cluster_pool_new(int threads)
{
	if (threads < 2)
		return NULL;
	cluster_pool_t *p = calloc(1, sizeof *p);
	if (!p)
		return NULL;
	p->thread = calloc(threads - 1, sizeof *p->thread);
	p->self = calloc(threads - 1, sizeof *p->self);
	if (!p->thread || !p->self) {
		free(p->thread);
		free(p->self);
		free(p);
		return NULL;
	}
	p->phase = KEEP; /* the first quantum starts a race */
	p->keep = KEEP_MIN / 2;   /* doubled by a first win of one thread */
	pthread_mutex_init(&p->lock, NULL);
	pthread_cond_init(&p->start, NULL);
	pthread_cond_init(&p->done, NULL);
	for (int i = 0; i < threads - 1; i++) {
		p->self[i] = (struct worker_t){ p, i };
		if (pthread_create(&p->thread[i], NULL, worker, &p->self[i]) != 0) {
			cluster_pool_free(p);
			return NULL;
		}
		p->workers++;
	}
	return p;
}

void cluster_pool_free(cluster_pool_t *p)
{
	if (!p)
		return;
	pthread_mutex_lock(&p->lock);
	atomic_store(&p->stop, 1);
	pthread_cond_broadcast(&p->start);
	pthread_mutex_unlock(&p->lock);
	for (int i = 0; i < p->workers; i++)
		pthread_join(p->thread[i], NULL);
	pthread_cond_destroy(&p->start);
	pthread_cond_destroy(&p->done);
	pthread_mutex_destroy(&p->lock);
	free(p->thread);
	free(p->self);
	free(p);
}

int cluster_pool_threads(const cluster_pool_t *p)
{
	return p ? p->workers + 1 : 1;
}

static uint64_t now_ns(void)
{
	struct timespec t;
	clock_gettime(CLOCK_MONOTONIC, &t);
	return (uint64_t)t.tv_sec * 1000000000u + (uint64_t)t.tv_nsec;
}

/* The mode of the next quantum, moving through the race's phases (the
 * pool goes first, so a short run uses it too). */
static int pick_mode(cluster_pool_t *p)
{
	if (p->phase_left == 0) {
		if (p->phase == TRY_SHARED) {
			p->phase = TRY_SOLO;
			p->mode = SOLO;
			p->phase_left = TRY_QUANTA;
		} else if (p->phase == TRY_SOLO) {
			/* ns per cycle, compared without dividing */
			unsigned __int128 solo = (unsigned __int128)p->tried_ns[SOLO] * p->tried_cycles[SHARED];
			unsigned __int128 shared = (unsigned __int128)p->tried_ns[SHARED] * p->tried_cycles[SOLO];
			p->phase = KEEP;
			p->mode = shared < solo ? SHARED : SOLO;
			/* a trial of the pool on a busy host is slow: back off */
			p->keep = p->mode == SHARED ? KEEP_MIN
				: p->keep * 2 > KEEP_MAX ? KEEP_MAX : p->keep * 2;
			p->phase_left = p->keep;
		} else {
			p->phase = TRY_SHARED;
			p->mode = SHARED;
			p->phase_left = TRY_QUANTA;
			p->tried_ns[SOLO] = p->tried_ns[SHARED] = 0;
			p->tried_cycles[SOLO] = p->tried_cycles[SHARED] = 0;
		}
	}
	p->phase_left--;
	return p->mode;
}

static void run_shared(cluster_pool_t *p, m162_t **mcu, int n, uint64_t end, int threads)
{
	atomic_store(&p->helpers, threads - 1);
	p->mcu = mcu;
	atomic_store_explicit(&p->n, n, memory_order_relaxed);
	p->end = end;
	atomic_store(&p->completed, 0);
	uint32_t gen = generation_of(atomic_load(&p->ticket)) + 1;
	pthread_mutex_lock(&p->lock);
	atomic_store(&p->ticket, (uint64_t)gen << 32);
	pthread_cond_broadcast(&p->start);
	pthread_mutex_unlock(&p->lock);
	run_share(p, gen);
	for (int k = 0; k < SPIN_ROUNDS && atomic_load(&p->completed) < n; k++)
		relax();
	if (atomic_load(&p->completed) < n) {
		pthread_mutex_lock(&p->lock);
		while (atomic_load(&p->completed) < n)
			pthread_cond_wait(&p->done, &p->lock);
		pthread_mutex_unlock(&p->lock);
	}
}

void cluster_pool_run(cluster_pool_t *p, m162_t **mcu, int n, uint64_t end, int threads,
		uint64_t cycles)
{
	if (n <= 0)
		return;
	if (threads > p->workers + 1)
		threads = p->workers + 1;
	int mode = pick_mode(p);
	uint64_t t0 = now_ns();
	if (mode == SHARED) {
		run_shared(p, mcu, n, end, threads);
	} else {
		for (int i = 0; i < n; i++)
			m162_run_until(mcu[i], end);
	}
	if (p->phase != KEEP) {
		p->tried_ns[mode] += now_ns() - t0;
		p->tried_cycles[mode] += cycles;
	}
}
