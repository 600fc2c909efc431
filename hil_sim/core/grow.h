/*
 * grow.h -- room for one more element at the end of a growing array.
 *
 * The logs and queues of the core (USART bytes, IR events, bytes for the PC)
 * all grow the same way: double the capacity when full, starting at
 * `first`.  On allocation failure the array is left as it was and the caller
 * drops the element (and counts it, where it matters).
 */
#ifndef HEXBOT_GROW_H
#define HEXBOT_GROW_H

#include <stddef.h>
#include <stdlib.h>

static inline int grow_array(void **data, size_t *cap, size_t len, size_t elem, size_t first)
{
	if (len < *cap)
		return 0;
	size_t more = *cap ? *cap * 2 : first;
	void *n = realloc(*data, more * elem);
	if (!n)
		return -1;
	*data = n;
	*cap = more;
	return 0;
}

/* 0 when arr[len] may be written, -1 when out of memory. */
#define GROW(arr, len, cap, first) \
	grow_array((void **)&(arr), &(cap), (len), sizeof *(arr), (first))

#endif
