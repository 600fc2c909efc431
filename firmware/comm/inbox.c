/* inbox.c - a FIFO of PC frames with one spare entry to assemble into. */
#include "inbox.h"

#include <string.h>

#define ENTRIES (INBOX_FRAMES + 1u) /* the kept frames + the one being assembled */

static inbox_entry_t entries[ENTRIES];
static uint8_t head;  /* oldest kept frame */
static uint8_t count; /* kept frames */

static uint8_t wrap(uint8_t i)
{
    return i >= ENTRIES ? (uint8_t)(i - ENTRIES) : i;
}

inbox_entry_t *inbox_slot(void)
{
    return &entries[wrap((uint8_t)(head + count))];
}

uint8_t inbox_keep(void)
{
    if (count == INBOX_FRAMES)
        return 0;
    count++;
    return 1;
}

uint8_t inbox_count(void)
{
    return count;
}

const inbox_entry_t *inbox_peek(uint8_t k)
{
    return &entries[wrap((uint8_t)(head + k))];
}

uint8_t inbox_take(inbox_entry_t *out)
{
    if (!count)
        return 0;
    memcpy(out, &entries[head], sizeof *out);
    head = wrap((uint8_t)(head + 1u));
    count--;
    return 1;
}

void inbox_clear(void)
{
    count = 0;
}
