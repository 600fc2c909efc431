#pragma once
// MESSAGE HEXBOT_STATUS PACKING

#include <stdint.h>

#define MAVLINK_MSG_ID_HEXBOT_STATUS 14002


typedef struct __mavlink_hexbot_status_t {
 uint32_t schema; /*<  Protocol schema hash the firmware was built from (HB_SCHEMA_HASH).*/
 uint8_t role; /*<  The module's role.*/
 uint8_t localized; /*<  1 when x, y and yref are known.*/
 int8_t x; /*<  Cell x (Table 4-1 coordinates).*/
 int8_t y; /*<  Cell y.*/
 uint8_t yref; /*<  Orientation 0..5: global side = body side + yref.*/
 uint8_t error; /*<  Last error.*/
 uint8_t crc_errors; /*<  MAVLink frames dropped for a bad checksum since boot (saturates at 255).*/
} mavlink_hexbot_status_t;

#define MAVLINK_MSG_ID_HEXBOT_STATUS_LEN 11
#define MAVLINK_MSG_ID_HEXBOT_STATUS_MIN_LEN 11
#define MAVLINK_MSG_ID_14002_LEN 11
#define MAVLINK_MSG_ID_14002_MIN_LEN 11

#define MAVLINK_MSG_ID_HEXBOT_STATUS_CRC 220
#define MAVLINK_MSG_ID_14002_CRC 220



#if MAVLINK_COMMAND_24BIT
#define MAVLINK_MESSAGE_INFO_HEXBOT_STATUS { \
    14002, \
    "HEXBOT_STATUS", \
    8, \
    {  { "schema", NULL, MAVLINK_TYPE_UINT32_T, 0, 0, offsetof(mavlink_hexbot_status_t, schema) }, \
         { "role", NULL, MAVLINK_TYPE_UINT8_T, 0, 4, offsetof(mavlink_hexbot_status_t, role) }, \
         { "localized", NULL, MAVLINK_TYPE_UINT8_T, 0, 5, offsetof(mavlink_hexbot_status_t, localized) }, \
         { "x", NULL, MAVLINK_TYPE_INT8_T, 0, 6, offsetof(mavlink_hexbot_status_t, x) }, \
         { "y", NULL, MAVLINK_TYPE_INT8_T, 0, 7, offsetof(mavlink_hexbot_status_t, y) }, \
         { "yref", NULL, MAVLINK_TYPE_UINT8_T, 0, 8, offsetof(mavlink_hexbot_status_t, yref) }, \
         { "error", NULL, MAVLINK_TYPE_UINT8_T, 0, 9, offsetof(mavlink_hexbot_status_t, error) }, \
         { "crc_errors", NULL, MAVLINK_TYPE_UINT8_T, 0, 10, offsetof(mavlink_hexbot_status_t, crc_errors) }, \
         } \
}
#else
#define MAVLINK_MESSAGE_INFO_HEXBOT_STATUS { \
    "HEXBOT_STATUS", \
    8, \
    {  { "schema", NULL, MAVLINK_TYPE_UINT32_T, 0, 0, offsetof(mavlink_hexbot_status_t, schema) }, \
         { "role", NULL, MAVLINK_TYPE_UINT8_T, 0, 4, offsetof(mavlink_hexbot_status_t, role) }, \
         { "localized", NULL, MAVLINK_TYPE_UINT8_T, 0, 5, offsetof(mavlink_hexbot_status_t, localized) }, \
         { "x", NULL, MAVLINK_TYPE_INT8_T, 0, 6, offsetof(mavlink_hexbot_status_t, x) }, \
         { "y", NULL, MAVLINK_TYPE_INT8_T, 0, 7, offsetof(mavlink_hexbot_status_t, y) }, \
         { "yref", NULL, MAVLINK_TYPE_UINT8_T, 0, 8, offsetof(mavlink_hexbot_status_t, yref) }, \
         { "error", NULL, MAVLINK_TYPE_UINT8_T, 0, 9, offsetof(mavlink_hexbot_status_t, error) }, \
         { "crc_errors", NULL, MAVLINK_TYPE_UINT8_T, 0, 10, offsetof(mavlink_hexbot_status_t, crc_errors) }, \
         } \
}
#endif

/**
 * @brief Pack a hexbot_status message
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param msg The MAVLink message to compress the data into
 *
 * @param schema  Protocol schema hash the firmware was built from (HB_SCHEMA_HASH).
 * @param role  The module's role.
 * @param localized  1 when x, y and yref are known.
 * @param x  Cell x (Table 4-1 coordinates).
 * @param y  Cell y.
 * @param yref  Orientation 0..5: global side = body side + yref.
 * @param error  Last error.
 * @param crc_errors  MAVLink frames dropped for a bad checksum since boot (saturates at 255).
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_hexbot_status_pack(uint8_t system_id, uint8_t component_id, mavlink_message_t* msg,
                               uint32_t schema, uint8_t role, uint8_t localized, int8_t x, int8_t y, uint8_t yref, uint8_t error, uint8_t crc_errors)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_HEXBOT_STATUS_LEN];
    _mav_put_uint32_t(buf, 0, schema);
    _mav_put_uint8_t(buf, 4, role);
    _mav_put_uint8_t(buf, 5, localized);
    _mav_put_int8_t(buf, 6, x);
    _mav_put_int8_t(buf, 7, y);
    _mav_put_uint8_t(buf, 8, yref);
    _mav_put_uint8_t(buf, 9, error);
    _mav_put_uint8_t(buf, 10, crc_errors);

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_HEXBOT_STATUS_LEN);
#else
    mavlink_hexbot_status_t packet;
    packet.schema = schema;
    packet.role = role;
    packet.localized = localized;
    packet.x = x;
    packet.y = y;
    packet.yref = yref;
    packet.error = error;
    packet.crc_errors = crc_errors;

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_HEXBOT_STATUS_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_HEXBOT_STATUS;
    return mavlink_finalize_message(msg, system_id, component_id, MAVLINK_MSG_ID_HEXBOT_STATUS_MIN_LEN, MAVLINK_MSG_ID_HEXBOT_STATUS_LEN, MAVLINK_MSG_ID_HEXBOT_STATUS_CRC);
}

/**
 * @brief Pack a hexbot_status message
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param status MAVLink status structure
 * @param msg The MAVLink message to compress the data into
 *
 * @param schema  Protocol schema hash the firmware was built from (HB_SCHEMA_HASH).
 * @param role  The module's role.
 * @param localized  1 when x, y and yref are known.
 * @param x  Cell x (Table 4-1 coordinates).
 * @param y  Cell y.
 * @param yref  Orientation 0..5: global side = body side + yref.
 * @param error  Last error.
 * @param crc_errors  MAVLink frames dropped for a bad checksum since boot (saturates at 255).
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_hexbot_status_pack_status(uint8_t system_id, uint8_t component_id, mavlink_status_t *_status, mavlink_message_t* msg,
                               uint32_t schema, uint8_t role, uint8_t localized, int8_t x, int8_t y, uint8_t yref, uint8_t error, uint8_t crc_errors)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_HEXBOT_STATUS_LEN];
    _mav_put_uint32_t(buf, 0, schema);
    _mav_put_uint8_t(buf, 4, role);
    _mav_put_uint8_t(buf, 5, localized);
    _mav_put_int8_t(buf, 6, x);
    _mav_put_int8_t(buf, 7, y);
    _mav_put_uint8_t(buf, 8, yref);
    _mav_put_uint8_t(buf, 9, error);
    _mav_put_uint8_t(buf, 10, crc_errors);

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_HEXBOT_STATUS_LEN);
#else
    mavlink_hexbot_status_t packet;
    packet.schema = schema;
    packet.role = role;
    packet.localized = localized;
    packet.x = x;
    packet.y = y;
    packet.yref = yref;
    packet.error = error;
    packet.crc_errors = crc_errors;

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_HEXBOT_STATUS_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_HEXBOT_STATUS;
#if MAVLINK_CRC_EXTRA
    return mavlink_finalize_message_buffer(msg, system_id, component_id, _status, MAVLINK_MSG_ID_HEXBOT_STATUS_MIN_LEN, MAVLINK_MSG_ID_HEXBOT_STATUS_LEN, MAVLINK_MSG_ID_HEXBOT_STATUS_CRC);
#else
    return mavlink_finalize_message_buffer(msg, system_id, component_id, _status, MAVLINK_MSG_ID_HEXBOT_STATUS_MIN_LEN, MAVLINK_MSG_ID_HEXBOT_STATUS_LEN);
#endif
}

/**
 * @brief Pack a hexbot_status message on a channel
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param chan The MAVLink channel this message will be sent over
 * @param msg The MAVLink message to compress the data into
 * @param schema  Protocol schema hash the firmware was built from (HB_SCHEMA_HASH).
 * @param role  The module's role.
 * @param localized  1 when x, y and yref are known.
 * @param x  Cell x (Table 4-1 coordinates).
 * @param y  Cell y.
 * @param yref  Orientation 0..5: global side = body side + yref.
 * @param error  Last error.
 * @param crc_errors  MAVLink frames dropped for a bad checksum since boot (saturates at 255).
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_hexbot_status_pack_chan(uint8_t system_id, uint8_t component_id, uint8_t chan,
                               mavlink_message_t* msg,
                                   uint32_t schema,uint8_t role,uint8_t localized,int8_t x,int8_t y,uint8_t yref,uint8_t error,uint8_t crc_errors)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_HEXBOT_STATUS_LEN];
    _mav_put_uint32_t(buf, 0, schema);
    _mav_put_uint8_t(buf, 4, role);
    _mav_put_uint8_t(buf, 5, localized);
    _mav_put_int8_t(buf, 6, x);
    _mav_put_int8_t(buf, 7, y);
    _mav_put_uint8_t(buf, 8, yref);
    _mav_put_uint8_t(buf, 9, error);
    _mav_put_uint8_t(buf, 10, crc_errors);

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_HEXBOT_STATUS_LEN);
#else
    mavlink_hexbot_status_t packet;
    packet.schema = schema;
    packet.role = role;
    packet.localized = localized;
    packet.x = x;
    packet.y = y;
    packet.yref = yref;
    packet.error = error;
    packet.crc_errors = crc_errors;

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_HEXBOT_STATUS_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_HEXBOT_STATUS;
    return mavlink_finalize_message_chan(msg, system_id, component_id, chan, MAVLINK_MSG_ID_HEXBOT_STATUS_MIN_LEN, MAVLINK_MSG_ID_HEXBOT_STATUS_LEN, MAVLINK_MSG_ID_HEXBOT_STATUS_CRC);
}

/**
 * @brief Encode a hexbot_status struct
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param msg The MAVLink message to compress the data into
 * @param hexbot_status C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_hexbot_status_encode(uint8_t system_id, uint8_t component_id, mavlink_message_t* msg, const mavlink_hexbot_status_t* hexbot_status)
{
    return mavlink_msg_hexbot_status_pack(system_id, component_id, msg, hexbot_status->schema, hexbot_status->role, hexbot_status->localized, hexbot_status->x, hexbot_status->y, hexbot_status->yref, hexbot_status->error, hexbot_status->crc_errors);
}

/**
 * @brief Encode a hexbot_status struct on a channel
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param chan The MAVLink channel this message will be sent over
 * @param msg The MAVLink message to compress the data into
 * @param hexbot_status C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_hexbot_status_encode_chan(uint8_t system_id, uint8_t component_id, uint8_t chan, mavlink_message_t* msg, const mavlink_hexbot_status_t* hexbot_status)
{
    return mavlink_msg_hexbot_status_pack_chan(system_id, component_id, chan, msg, hexbot_status->schema, hexbot_status->role, hexbot_status->localized, hexbot_status->x, hexbot_status->y, hexbot_status->yref, hexbot_status->error, hexbot_status->crc_errors);
}

/**
 * @brief Encode a hexbot_status struct with provided status structure
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param status MAVLink status structure
 * @param msg The MAVLink message to compress the data into
 * @param hexbot_status C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_hexbot_status_encode_status(uint8_t system_id, uint8_t component_id, mavlink_status_t* _status, mavlink_message_t* msg, const mavlink_hexbot_status_t* hexbot_status)
{
    return mavlink_msg_hexbot_status_pack_status(system_id, component_id, _status, msg,  hexbot_status->schema, hexbot_status->role, hexbot_status->localized, hexbot_status->x, hexbot_status->y, hexbot_status->yref, hexbot_status->error, hexbot_status->crc_errors);
}

/**
 * @brief Send a hexbot_status message
 * @param chan MAVLink channel to send the message
 *
 * @param schema  Protocol schema hash the firmware was built from (HB_SCHEMA_HASH).
 * @param role  The module's role.
 * @param localized  1 when x, y and yref are known.
 * @param x  Cell x (Table 4-1 coordinates).
 * @param y  Cell y.
 * @param yref  Orientation 0..5: global side = body side + yref.
 * @param error  Last error.
 * @param crc_errors  MAVLink frames dropped for a bad checksum since boot (saturates at 255).
 */
#ifdef MAVLINK_USE_CONVENIENCE_FUNCTIONS

static inline void mavlink_msg_hexbot_status_send(mavlink_channel_t chan, uint32_t schema, uint8_t role, uint8_t localized, int8_t x, int8_t y, uint8_t yref, uint8_t error, uint8_t crc_errors)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_HEXBOT_STATUS_LEN];
    _mav_put_uint32_t(buf, 0, schema);
    _mav_put_uint8_t(buf, 4, role);
    _mav_put_uint8_t(buf, 5, localized);
    _mav_put_int8_t(buf, 6, x);
    _mav_put_int8_t(buf, 7, y);
    _mav_put_uint8_t(buf, 8, yref);
    _mav_put_uint8_t(buf, 9, error);
    _mav_put_uint8_t(buf, 10, crc_errors);

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_HEXBOT_STATUS, buf, MAVLINK_MSG_ID_HEXBOT_STATUS_MIN_LEN, MAVLINK_MSG_ID_HEXBOT_STATUS_LEN, MAVLINK_MSG_ID_HEXBOT_STATUS_CRC);
#else
    mavlink_hexbot_status_t packet;
    packet.schema = schema;
    packet.role = role;
    packet.localized = localized;
    packet.x = x;
    packet.y = y;
    packet.yref = yref;
    packet.error = error;
    packet.crc_errors = crc_errors;

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_HEXBOT_STATUS, (const char *)&packet, MAVLINK_MSG_ID_HEXBOT_STATUS_MIN_LEN, MAVLINK_MSG_ID_HEXBOT_STATUS_LEN, MAVLINK_MSG_ID_HEXBOT_STATUS_CRC);
#endif
}

/**
 * @brief Send a hexbot_status message
 * @param chan MAVLink channel to send the message
 * @param struct The MAVLink struct to serialize
 */
static inline void mavlink_msg_hexbot_status_send_struct(mavlink_channel_t chan, const mavlink_hexbot_status_t* hexbot_status)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    mavlink_msg_hexbot_status_send(chan, hexbot_status->schema, hexbot_status->role, hexbot_status->localized, hexbot_status->x, hexbot_status->y, hexbot_status->yref, hexbot_status->error, hexbot_status->crc_errors);
#else
    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_HEXBOT_STATUS, (const char *)hexbot_status, MAVLINK_MSG_ID_HEXBOT_STATUS_MIN_LEN, MAVLINK_MSG_ID_HEXBOT_STATUS_LEN, MAVLINK_MSG_ID_HEXBOT_STATUS_CRC);
#endif
}

#if MAVLINK_MSG_ID_HEXBOT_STATUS_LEN <= MAVLINK_MAX_PAYLOAD_LEN
/*
  This variant of _send() can be used to save stack space by reusing
  memory from the receive buffer.  The caller provides a
  mavlink_message_t which is the size of a full mavlink message. This
  is usually the receive buffer for the channel, and allows a reply to an
  incoming message with minimum stack space usage.
 */
static inline void mavlink_msg_hexbot_status_send_buf(mavlink_message_t *msgbuf, mavlink_channel_t chan,  uint32_t schema, uint8_t role, uint8_t localized, int8_t x, int8_t y, uint8_t yref, uint8_t error, uint8_t crc_errors)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char *buf = (char *)msgbuf;
    _mav_put_uint32_t(buf, 0, schema);
    _mav_put_uint8_t(buf, 4, role);
    _mav_put_uint8_t(buf, 5, localized);
    _mav_put_int8_t(buf, 6, x);
    _mav_put_int8_t(buf, 7, y);
    _mav_put_uint8_t(buf, 8, yref);
    _mav_put_uint8_t(buf, 9, error);
    _mav_put_uint8_t(buf, 10, crc_errors);

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_HEXBOT_STATUS, buf, MAVLINK_MSG_ID_HEXBOT_STATUS_MIN_LEN, MAVLINK_MSG_ID_HEXBOT_STATUS_LEN, MAVLINK_MSG_ID_HEXBOT_STATUS_CRC);
#else
    mavlink_hexbot_status_t *packet = (mavlink_hexbot_status_t *)msgbuf;
    packet->schema = schema;
    packet->role = role;
    packet->localized = localized;
    packet->x = x;
    packet->y = y;
    packet->yref = yref;
    packet->error = error;
    packet->crc_errors = crc_errors;

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_HEXBOT_STATUS, (const char *)packet, MAVLINK_MSG_ID_HEXBOT_STATUS_MIN_LEN, MAVLINK_MSG_ID_HEXBOT_STATUS_LEN, MAVLINK_MSG_ID_HEXBOT_STATUS_CRC);
#endif
}
#endif

#endif

// MESSAGE HEXBOT_STATUS UNPACKING


/**
 * @brief Get field schema from hexbot_status message
 *
 * @return  Protocol schema hash the firmware was built from (HB_SCHEMA_HASH).
 */
static inline uint32_t mavlink_msg_hexbot_status_get_schema(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint32_t(msg,  0);
}

/**
 * @brief Get field role from hexbot_status message
 *
 * @return  The module's role.
 */
static inline uint8_t mavlink_msg_hexbot_status_get_role(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint8_t(msg,  4);
}

/**
 * @brief Get field localized from hexbot_status message
 *
 * @return  1 when x, y and yref are known.
 */
static inline uint8_t mavlink_msg_hexbot_status_get_localized(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint8_t(msg,  5);
}

/**
 * @brief Get field x from hexbot_status message
 *
 * @return  Cell x (Table 4-1 coordinates).
 */
static inline int8_t mavlink_msg_hexbot_status_get_x(const mavlink_message_t* msg)
{
    return _MAV_RETURN_int8_t(msg,  6);
}

/**
 * @brief Get field y from hexbot_status message
 *
 * @return  Cell y.
 */
static inline int8_t mavlink_msg_hexbot_status_get_y(const mavlink_message_t* msg)
{
    return _MAV_RETURN_int8_t(msg,  7);
}

/**
 * @brief Get field yref from hexbot_status message
 *
 * @return  Orientation 0..5: global side = body side + yref.
 */
static inline uint8_t mavlink_msg_hexbot_status_get_yref(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint8_t(msg,  8);
}

/**
 * @brief Get field error from hexbot_status message
 *
 * @return  Last error.
 */
static inline uint8_t mavlink_msg_hexbot_status_get_error(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint8_t(msg,  9);
}

/**
 * @brief Get field crc_errors from hexbot_status message
 *
 * @return  MAVLink frames dropped for a bad checksum since boot (saturates at 255).
 */
static inline uint8_t mavlink_msg_hexbot_status_get_crc_errors(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint8_t(msg,  10);
}

/**
 * @brief Decode a hexbot_status message into a struct
 *
 * @param msg The message to decode
 * @param hexbot_status C-struct to decode the message contents into
 */
static inline void mavlink_msg_hexbot_status_decode(const mavlink_message_t* msg, mavlink_hexbot_status_t* hexbot_status)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    hexbot_status->schema = mavlink_msg_hexbot_status_get_schema(msg);
    hexbot_status->role = mavlink_msg_hexbot_status_get_role(msg);
    hexbot_status->localized = mavlink_msg_hexbot_status_get_localized(msg);
    hexbot_status->x = mavlink_msg_hexbot_status_get_x(msg);
    hexbot_status->y = mavlink_msg_hexbot_status_get_y(msg);
    hexbot_status->yref = mavlink_msg_hexbot_status_get_yref(msg);
    hexbot_status->error = mavlink_msg_hexbot_status_get_error(msg);
    hexbot_status->crc_errors = mavlink_msg_hexbot_status_get_crc_errors(msg);
#else
        uint8_t len = msg->len < MAVLINK_MSG_ID_HEXBOT_STATUS_LEN? msg->len : MAVLINK_MSG_ID_HEXBOT_STATUS_LEN;
        memset(hexbot_status, 0, MAVLINK_MSG_ID_HEXBOT_STATUS_LEN);
    memcpy(hexbot_status, _MAV_PAYLOAD(msg), len);
#endif
}
