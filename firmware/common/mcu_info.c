/* mcu_info.c - what the ELF says about its target: part name and clock for
 * simavr (.mmcu section, not loaded into flash) and the fuse bytes of
 * Table 3-6 (.fuse section), both from one place: hexbot_codes.h; and, in
 * flash, what the image is (board, version, protocol schema), so that the
 * simulator and `hexbot flash` can check a file before it runs. */
#include <avr/io.h>

#include "avr_mcu_section.h"
#include "hexbot_codes.h"
#include "image_mark.h"

AVR_MCU(F_CPU, "atmega162");

FUSES = {
    .low = HB_FUSE_LOW,
    .high = HB_FUSE_HIGH,
    .extended = HB_FUSE_EXTENDED,
};

/* HB_IMAGE is the image's name, set by the Makefile for each image; the
 * linker keeps the mark although nothing reads it (--undefined). */
const char hb_image_mark[] PROGMEM = HB_IMAGE_MARK(HB_IMAGE);
