/* localize.h - cluster localization by MSG1 flooding (code 66). */
#ifndef LOCALIZE_H
#define LOCALIZE_H

#include <stdint.h>

#include "system.h"

/* Timing, in 10 ms ticks (300 baud: one byte = 3.33 ticks, MSG1 = 27):
 * a listener stays LISTEN ticks on each side waiting for any byte; when one
 * comes it stays up to CATCH ticks for a whole MSG1. A teacher therefore
 * repeats MSG1 on each side for DWELL >= 6 x LISTEN + CATCH ticks, so that
 * a listener cycling through its sides finds it. */
#define LOC_LISTEN_TICKS 8u
#define LOC_CATCH_TICKS 60u
#define LOC_DWELL_TICKS (6u * LOC_LISTEN_TICKS + LOC_CATCH_TICKS + 10u)
#define LOC_SWEEP_TICKS (6u * LOC_DWELL_TICKS)
/* The flood runs for a fixed window from the end of the 66 frame (common
 * to every module that heard it), long enough for LOC_HOPS hops from a
 * localized module; then every module answers in its slot. */
#define LOC_HOPS 3u
#define LOC_WINDOW_TICKS (LOC_HOPS * (LOC_SWEEP_TICKS + 6u * LOC_LISTEN_TICKS) + 20u)

typedef enum { LOC_KNOWN = 0, LOC_LEARNED, LOC_NOT_HEARD } loc_result_t;

/** Take part in one localization flood (blocks for LOC_WINDOW_TICKS). */
loc_result_t localize_run(tick_t started);

#endif /* LOCALIZE_H */
