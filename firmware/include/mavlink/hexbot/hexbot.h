/** @file
 *  @brief MAVLink comm protocol generated from hexbot.xml
 *  @see http://mavlink.org
 */
#pragma once
#ifndef MAVLINK_HEXBOT_H
#define MAVLINK_HEXBOT_H

#ifndef MAVLINK_H
    #error Wrong include order: MAVLINK_HEXBOT.H MUST NOT BE DIRECTLY USED. Include mavlink.h from the same directory instead or set ALL AND EVERY defines from MAVLINK.H manually accordingly, including the #define MAVLINK_H call.
#endif

#define MAVLINK_HEXBOT_XML_HASH 5553977128620493510

#ifdef __cplusplus
extern "C" {
#endif

// MESSAGE LENGTHS AND CRCS

#ifndef MAVLINK_MESSAGE_LENGTHS
#define MAVLINK_MESSAGE_LENGTHS {}
#endif

#ifndef MAVLINK_MESSAGE_CRCS
#define MAVLINK_MESSAGE_CRCS {{0, 50, 9, 9, 0, 0, 0}, {14000, 229, 10, 10, 1, 0, 0}, {14001, 87, 4, 4, 0, 0, 0}, {14002, 220, 11, 11, 0, 0, 0}, {14003, 35, 4, 4, 0, 0, 0}}
#endif

#include "../protocol.h"

#define MAVLINK_ENABLED_HEXBOT

// ENUM DEFINITIONS


/** @brief Function codes of Table 3-7 and our extensions. */
#ifndef HAVE_ENUM_HEXBOT_FUNCTION
#define HAVE_ENUM_HEXBOT_FUNCTION
typedef enum HEXBOT_FUNCTION
{
   HEXBOT_FUNCTION_JX_OPEN=1, /* JxOpen(i): Open a solenoid (control board). | */
   HEXBOT_FUNCTION_JX_CLOSE=2, /* JxClose(i): Close a solenoid (control board). | */
   HEXBOT_FUNCTION_JX_OPEN_ALL=3, /* JxOpenAll(): Open all solenoids (control board). | */
   HEXBOT_FUNCTION_JX_CLOSE_ALL=4, /* JxCloseAll(): Close all solenoids (control board). | */
   HEXBOT_FUNCTION_JTEST=5, /* JTest(n, t): Open all solenoids alternately (control board). | */
   HEXBOT_FUNCTION_SX_P=11, /* SxP(i): Turn on a magnet (positive pole) (control board). | */
   HEXBOT_FUNCTION_SX_N=12, /* SxN(i): Turn on a magnet (negative pole) (control board). | */
   HEXBOT_FUNCTION_SX_OFF=13, /* SxOff(i): Turn off a magnet (control board). | */
   HEXBOT_FUNCTION_SX_OFF_ALL=14, /* SxOffAll(): Turn off all magnets (control board). | */
   HEXBOT_FUNCTION_SPTEST=15, /* SPTest(n, t): Turn on all magnets alternately (positive pole) (control board). | */
   HEXBOT_FUNCTION_SNTEST=16, /* SNTest(n, t): Turn on all magnets alternately (negative pole) (control board). | */
   HEXBOT_FUNCTION_TURN_OFF_ALL=20, /* TurnOffAll(): Turn off all actuators (control board). | */
   HEXBOT_FUNCTION_MCW=21, /* MCW(i, t1, t2, t3): Mobile module clockwise rotation (control board). | */
   HEXBOT_FUNCTION_MCCW=22, /* MCCW(i, t1, t2, t3): Mobile module counterclockwise rotation (control board). | */
   HEXBOT_FUNCTION_SCW=23, /* SCW(i, t1, t2, t3): Substrate clockwise support (control board). | */
   HEXBOT_FUNCTION_SCCW=24, /* SCCW(i, t1, t2, t3): Substrate counterclockwise support (control board). | */
   HEXBOT_FUNCTION_IR_SEL=25, /* IrSel(i): UART1 (IR) channel selection (comm board). | */
   HEXBOT_FUNCTION_SIDE_ON_P=28, /* SideOnP(i): Positive magnet on LED (comm board). | */
   HEXBOT_FUNCTION_SIDE_OFF_P=29, /* SideOffP(i): Positive magnet off LED (comm board). | */
   HEXBOT_FUNCTION_SIDE_ON_ALL_P=30, /* SideOnAllP(): All positive LEDs on (comm board). | */
   HEXBOT_FUNCTION_SIDE_OFF_ALL_P=31, /* SideOffAllP(): All positive LEDs off (comm board). | */
   HEXBOT_FUNCTION_SIDE_ON_N=32, /* SideOnN(i): Negative magnet on LED (comm board). | */
   HEXBOT_FUNCTION_SIDE_OFF_N=33, /* SideOffN(i): Negative magnet off LED (comm board). | */
   HEXBOT_FUNCTION_SIDE_ON_ALL_N=34, /* SideOnAllN(): All negative LEDs on (comm board). | */
   HEXBOT_FUNCTION_SIDE_OFF_ALL_N=35, /* SideOffAllN(): All negative LEDs off (comm board). | */
   HEXBOT_FUNCTION_SIDE_PTEST=36, /* SidePTest(n, t): Positive magnet LEDs in turn (comm board). | */
   HEXBOT_FUNCTION_SIDE_NTEST=37, /* SideNTest(n, t): Negative magnet LEDs in turn (comm board). | */
   HEXBOT_FUNCTION_JOINT_ON=38, /* JointOn(i): Joint on LED (comm board). | */
   HEXBOT_FUNCTION_JOINT_OFF=39, /* JointOff(i): Joint off LED (comm board). | */
   HEXBOT_FUNCTION_JOINT_ON_ALL=40, /* JointOnAll(): All joint LEDs on (comm board). | */
   HEXBOT_FUNCTION_JOINT_OFF_ALL=41, /* JointOffAll(): All joint LEDs off (comm board). | */
   HEXBOT_FUNCTION_JOINT_TEST=43, /* JointTest(n, t): Joint LEDs in turn (comm board). | */
   HEXBOT_FUNCTION_LON=44, /* LOn(): All LEDs on (comm board). | */
   HEXBOT_FUNCTION_LOFF=45, /* LOff(): All LEDs off (comm board). | */
   HEXBOT_FUNCTION_LCIRCLE=46, /* LCircle(n, t): Rotating LEDs (comm board). | */
   HEXBOT_FUNCTION_LCOLOR=47, /* LColor(n, t): Rotating LED colours (comm board). | */
   HEXBOT_FUNCTION_LFLASH1=48, /* LFlash1(n, t): Flashing LEDs, pattern 1 (comm board). | */
   HEXBOT_FUNCTION_LFLASH2=49, /* LFlash2(n, t): Flashing LEDs, pattern 2 (comm board). | */
   HEXBOT_FUNCTION_LYREF=50, /* LYref(i): Reference (orientation) indicating LEDs (comm board). | */
   HEXBOT_FUNCTION_LMCW=56, /* LMCW(i, t1, t2, t3): Mobile clockwise rotation LEDs (comm board). | */
   HEXBOT_FUNCTION_LMCCW=57, /* LMCCW(i, t1, t2, t3): Mobile counterclockwise rotation LEDs (comm board). | */
   HEXBOT_FUNCTION_LSCW=58, /* LSCW(i, t1, t2, t3): Substrate clockwise support LEDs (comm board). | */
   HEXBOT_FUNCTION_LSCCW=59, /* LSCCW(i, t1, t2, t3): Substrate counterclockwise support LEDs (comm board). | */
   HEXBOT_FUNCTION_REF=65, /* Ref(): Set the module as the reference at (0,0), Yref 0, role S (comm board). | */
   HEXBOT_FUNCTION_LOCALIZE=66, /* Localize(): Start localization; spreads over the connected cluster (comm board). | */
   HEXBOT_FUNCTION_CW=67, /* CW(si, st1, st2, st3, mi, mt1, mt2, mt3): Combined clockwise rotation; each module runs its role's half (comm board). | */
   HEXBOT_FUNCTION_CCW=68, /* CCW(si, st1, st2, st3, mi, mt1, mt2, mt3): Combined counterclockwise rotation; each module runs its role's half (comm board). | */
   HEXBOT_FUNCTION_SELECT=69, /* Select(id, id, id, id, id, id, id, id): Address the following commands to these modules (0 = all) (comm board). | */
   HEXBOT_FUNCTION_STATUS=70, /* Status(): Report id, role, localized flag, X, Y, Yref and last error (comm board). | */
   HEXBOT_FUNCTION_SET_ROLE=71, /* SetRole(role): Set the module's role for combined rotations (comm board). | */
   HEXBOT_FUNCTION_CLEAR_ERROR=72, /* ClearError(): Clear the last error (comm board). | */
   HEXBOT_FUNCTION_ENUM_END=73, /*  | */
} HEXBOT_FUNCTION;
#endif

/** @brief How a module answered a command. */
#ifndef HAVE_ENUM_HEXBOT_RESULT
#define HAVE_ENUM_HEXBOT_RESULT
typedef enum HEXBOT_RESULT
{
   HEXBOT_RESULT_DONE=0, /* The function ran (legacy ACK with the command's code). | */
   HEXBOT_RESULT_ERROR=1, /* Refused with an error reason in field error (legacy ERR). | */
   HEXBOT_RESULT_UNUSED_CODE=2, /* The code names no function; nothing done (legacy ACK 'N'). | */
   HEXBOT_RESULT_CONTROL_TIMEOUT=3, /* The control board did not echo within 2.5 s (legacy ACK '~'). | */
   HEXBOT_RESULT_ENUM_END=4, /*  | */
} HEXBOT_RESULT;
#endif

/** @brief Error reasons (legacy ERR reason byte). */
#ifndef HAVE_ENUM_HEXBOT_ERROR
#define HAVE_ENUM_HEXBOT_ERROR
typedef enum HEXBOT_ERROR
{
   HEXBOT_ERROR_NONE=0, /* none | */
   HEXBOT_ERROR_ARG_RANGE=1, /* arg range | */
   HEXBOT_ERROR_CONTROL_TIMEOUT=2, /* control timeout | */
   HEXBOT_ERROR_CONTROL_MISMATCH=3, /* control mismatch | */
   HEXBOT_ERROR_NOT_LOCALIZED=4, /* not localized | */
   HEXBOT_ERROR_BAD_FRAME=5, /* bad frame | */
   HEXBOT_ERROR_NO_ROLE=6, /* no role | */
   HEXBOT_ERROR_NOT_HEARD=7, /* not heard | */
   HEXBOT_ERROR_BUSY=8, /* busy | */
   HEXBOT_ERROR_STOPPED=9, /* stopped | */
   HEXBOT_ERROR_WATCHDOG_RESET=10, /* watchdog reset | */
   HEXBOT_ERROR_BROWN_OUT=11, /* brown out | */
   HEXBOT_ERROR_CONTROL_RESTARTED=12, /* control restarted | */
   HEXBOT_ERROR_ENUM_END=13, /*  | */
} HEXBOT_ERROR;
#endif

/** @brief Role of a module in combined rotations. */
#ifndef HAVE_ENUM_HEXBOT_ROLE
#define HAVE_ENUM_HEXBOT_ROLE
typedef enum HEXBOT_ROLE
{
   HEXBOT_ROLE_NONE=0, /* '-' | */
   HEXBOT_ROLE_MOBILE=1, /* 'M' | */
   HEXBOT_ROLE_SUBSTRATE=2, /* 'S' | */
   HEXBOT_ROLE_ENUM_END=3, /*  | */
} HEXBOT_ROLE;
#endif

// MAVLINK VERSION

#ifndef MAVLINK_VERSION
#define MAVLINK_VERSION 1
#endif

#if (MAVLINK_VERSION == 0)
#undef MAVLINK_VERSION
#define MAVLINK_VERSION 1
#endif

// MESSAGE DEFINITIONS
#include "./mavlink_msg_hexbot_command.h"
#include "./mavlink_msg_hexbot_ack.h"
#include "./mavlink_msg_hexbot_status.h"
#include "./mavlink_msg_hexbot_localized.h"

// base include
#include "../minimal/minimal.h"


#if MAVLINK_HEXBOT_XML_HASH == MAVLINK_PRIMARY_XML_HASH
# define MAVLINK_MESSAGE_INFO {MAVLINK_MESSAGE_INFO_HEARTBEAT, MAVLINK_MESSAGE_INFO_HEXBOT_COMMAND, MAVLINK_MESSAGE_INFO_HEXBOT_ACK, MAVLINK_MESSAGE_INFO_HEXBOT_STATUS, MAVLINK_MESSAGE_INFO_HEXBOT_LOCALIZED}
# define MAVLINK_MESSAGE_NAMES {{ "HEARTBEAT", 0 }, { "HEXBOT_ACK", 14001 }, { "HEXBOT_COMMAND", 14000 }, { "HEXBOT_LOCALIZED", 14003 }, { "HEXBOT_STATUS", 14002 }}
# if MAVLINK_COMMAND_24BIT
#  include "../mavlink_get_info.h"
# endif
#endif

#ifdef __cplusplus
}
#endif // __cplusplus
#endif // MAVLINK_HEXBOT_H
