/* image_mark.h - what this image is, in its flash (mcu_info.c), for whoever
 * holds the file (the simulator, `hexbot flash`; protocol/image_mark.py):
 *
 *     hexbot-image board=comm version=0.1.0 schema=c9e4afd8
 *
 * The comm board's Status reply sends the schema from here, so an image
 * holds one copy of it. */
#ifndef IMAGE_MARK_H
#define IMAGE_MARK_H

#include <avr/pgmspace.h>

#include "hexbot_codes.h"
#include "version.h"

extern const char hb_image_mark[] PROGMEM;

/* The schema's hex digits: the mark ends with them. */
#define HB_IMAGE_MARK_SCHEMA \
    (hb_image_mark + sizeof(HB_IMAGE_MARK(HB_IMAGE)) - sizeof(HB_SCHEMA_HASH_TEXT))

#endif /* IMAGE_MARK_H */
