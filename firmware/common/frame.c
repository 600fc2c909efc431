/* frame.c - fixed-length frame receiver with resynchronisation. */
#include "frame.h"

#include <string.h>

#include "hexbot_codes.h"

void frame_init(frame_rx_t *f, uint8_t size, tick_t timeout)
{
    memset(f, 0, sizeof(*f));
    f->size = size;
    f->timeout = timeout;
}

/* Keep the bytes from the first '*' after the frame start, if any. */
static void resync(frame_rx_t *f)
{
    uint8_t i;
    for (i = 1; i < f->len; i++) {
        if (f->buf[i] == HB_START)
            break;
    }
    f->len = (uint8_t)(f->len - i);
    memmove(f->buf, f->buf + i, f->len);
}

frame_result_t frame_push(frame_rx_t *f, uint8_t b)
{
    frame_result_t r = frame_expire(f);
    f->last = tick_now();
    if (f->len == 0) {
        if (b == HB_START)
            f->buf[f->len++] = b;
        return r;
    }
    f->buf[f->len++] = b;
    if (f->len < f->size)
        return r;
    if (b == HB_END) {
        f->len = 0;
        return FRAME_DONE;
    }
    resync(f);
    return FRAME_DROPPED;
}

void frame_resume(frame_rx_t *f, uint8_t from)
{
    f->len = (uint8_t)(f->size - from);
    memmove(f->buf, f->buf + from, f->len);
    f->last = tick_now();
}

frame_result_t frame_expire(frame_rx_t *f)
{
    if (f->len && tick_since(f->last) > f->timeout) {
        f->len = 0;
        return FRAME_DROPPED;
    }
    return FRAME_NONE;
}

tick_t frame_due(const frame_rx_t *f, tick_t due)
{
    if (!f->len)
        return due;
    return tick_earlier(due, (tick_t)(f->last + f->timeout + 1u));
}
