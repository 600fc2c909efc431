/* version.h - firmware version string, set with `make VERSION=...`. */
#ifndef VERSION_H
#define VERSION_H

#ifndef HB_FW_VERSION
#define HB_FW_VERSION "0.0.0"
#endif

#endif /* VERSION_H */
