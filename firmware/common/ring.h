/* ring.h - single-producer, single-consumer byte ring buffer.
 *
 * Contract (as LUFA's RingBuffer.h): exactly one producer (an interrupt
 * handler or the main loop) calls ring_put, exactly one consumer calls
 * ring_get. Head and tail are single bytes, so each side reads the other's
 * index atomically; no locking is needed. RING_SIZE must be a power of two.
 * A compiler barrier orders the data access before the index is published
 * (the AVR has no memory reordering, but gcc may move a non-volatile store
 * past a volatile one).
 */
#ifndef RING_H
#define RING_H

#include <stdint.h>

#define RING_SIZE 32u
#define RING_MASK (RING_SIZE - 1u)
#define RING_BARRIER() __asm__ __volatile__("" ::: "memory")

typedef struct {
    volatile uint8_t head; /* next slot the producer writes */
    volatile uint8_t tail; /* next slot the consumer reads */
    uint8_t data[RING_SIZE];
} ring_t;

static inline uint8_t ring_count(const ring_t *r)
{
    return (uint8_t)(r->head - r->tail) & RING_MASK;
}

static inline uint8_t ring_full(const ring_t *r)
{
    return ring_count(r) == RING_MASK;
}

/** Append a byte; returns 0 (byte dropped) when the ring is full. */
static inline uint8_t ring_put(ring_t *r, uint8_t b)
{
    uint8_t h = r->head;
    uint8_t next = (uint8_t)(h + 1u) & RING_MASK;
    if (next == r->tail)
        return 0;
    r->data[h] = b;
    RING_BARRIER(); /* the byte is in place before the consumer can see it */
    r->head = next;
    return 1;
}

/** Remove the oldest byte; returns -1 when the ring is empty. */
static inline int16_t ring_get(ring_t *r)
{
    uint8_t t = r->tail;
    if (t == r->head)
        return -1;
    uint8_t b = r->data[t];
    RING_BARRIER(); /* read the byte before handing its slot back */
    r->tail = (uint8_t)(t + 1u) & RING_MASK;
    return b;
}

/** Consumer side: forget everything received so far. */
static inline void ring_clear(ring_t *r)
{
    r->tail = r->head;
}

#endif /* RING_H */
