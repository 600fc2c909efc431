/* mcu_info.c - what the ELF says about its target: part name and clock for
 * simavr (.mmcu section, not loaded into flash) and the fuse bytes of
 * Table 3-6 (.fuse section), both from one place: hexbot_codes.h. */
#include <avr/io.h>

#include "avr_mcu_section.h"
#include "hexbot_codes.h"

AVR_MCU(F_CPU, "atmega162");

FUSES = {
    .low = HB_FUSE_LOW,
    .high = HB_FUSE_HIGH,
    .extended = HB_FUSE_EXTENDED,
};
