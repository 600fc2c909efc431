/*
 * raw_simavr.c -- simavr's own run loop (avr_callback_run_raw) on one MCU,
 * timed: the reference the simulator's speed is measured against
 * (`hexbot bench sim`, `hexbot bench sim-core`).
 *
 *   build/raw_simavr CORE ELF CYCLES     prints "CYCLES_DONE SECONDS"
 *
 * CORE is a stock simavr core (atmega128, atmega644, ...) or atmega162, our
 * core from hil_sim/core under the same stock loop.  Kept out of the Python
 * extension so that the simulator's run loop has no comparison mode.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "../hil_sim/core/m162.h"

int main(int argc, char **argv)
{
	if (argc != 4) {
		fprintf(stderr, "usage: %s CORE ELF CYCLES\n", argv[0]);
		return 2;
	}
	const char *core = argv[1], *elf = argv[2];
	uint64_t cycles = strtoull(argv[3], NULL, 0);
	char err[512];

	m162_install_logger(); /* simavr prints nothing */
	m162_t *m = strcmp(core, "atmega162") ? m162_make_stock(core) : m162_make();
	if (!m) {
		fprintf(stderr, "%s: unknown MCU core '%s'\n", argv[0], core);
		return 1;
	}
	if (m162_load_elf(m, elf, err, sizeof err) != 0) {
		fprintf(stderr, "%s: %s\n", argv[0], err);
		return 1;
	}
	avr_t *avr = m->avr;
	/* simavr's own loop, exactly as its run_avr does it (minus wall-clock
	 * sleep: the wrapper's sleep callback is virtual) */
	avr->run = avr_callback_run_raw;
	/* wall and CPU time: on a shared machine the CPU time is the fair
	 * reference (other processes take wall time, not CPU time) */
	struct timespec t0, t1, c0, c1;
	clock_gettime(CLOCK_MONOTONIC, &t0);
	clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &c0);
	int state = cpu_Running;
	while (avr->cycle < cycles && (state == cpu_Running || state == cpu_Sleeping))
		state = avr_run(avr);
	clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &c1);
	clock_gettime(CLOCK_MONOTONIC, &t1);
	printf("%llu %.9f %.9f\n", (unsigned long long)avr->cycle,
			(t1.tv_sec - t0.tv_sec) + (t1.tv_nsec - t0.tv_nsec) * 1e-9,
			(c1.tv_sec - c0.tv_sec) + (c1.tv_nsec - c0.tv_nsec) * 1e-9);
	m162_free(m);
	return 0;
}
