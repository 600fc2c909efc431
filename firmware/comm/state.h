/* state.h - what the communication board knows about its module. */
#ifndef STATE_H
#define STATE_H

#include <stdint.h>

typedef struct {
    uint8_t id;          /* DIP switches of the control board, from the handshake */
    uint8_t role;        /* HB_ROLE_MOBILE (default) or HB_ROLE_SUBSTRATE */
    uint8_t localized;   /* position and yref are valid */
    uint8_t reference;   /* set by Ref(): keeps (0,0) and teaches first */
    int8_t x, y;         /* cell, Table 4-1 coordinates */
    uint8_t yref;        /* orientation: global side = body side + yref */
    uint8_t heard_side;  /* global side MSG1 was heard through (1..6) */
    uint8_t last_error;  /* HB_ERR_* */
    uint8_t addressed;   /* a Select has been received since boot */
    uint8_t selected;    /* addressed mode: this module is in the last Select */
    uint8_t rank;        /* addressed mode: answer after rank reply slots */
    uint8_t control_up;  /* the control board said "listening" */
} module_state_t;

extern module_state_t g_state;

#endif /* STATE_H */
