#pragma once
// MESSAGE HEXBOT_LOCALIZED PACKING

#include <stdint.h>

#define MAVLINK_MSG_ID_HEXBOT_LOCALIZED 14003


typedef struct __mavlink_hexbot_localized_t {
 uint8_t side; /*<  Global side 1..6 the neighbour's message came through.*/
 uint8_t yref; /*<  Orientation 0..5.*/
 int8_t x; /*<  Cell x.*/
 int8_t y; /*<  Cell y.*/
} mavlink_hexbot_localized_t;

#define MAVLINK_MSG_ID_HEXBOT_LOCALIZED_LEN 4
#define MAVLINK_MSG_ID_HEXBOT_LOCALIZED_MIN_LEN 4
#define MAVLINK_MSG_ID_14003_LEN 4
#define MAVLINK_MSG_ID_14003_MIN_LEN 4

#define MAVLINK_MSG_ID_HEXBOT_LOCALIZED_CRC 35
#define MAVLINK_MSG_ID_14003_CRC 35



#if MAVLINK_COMMAND_24BIT
#define MAVLINK_MESSAGE_INFO_HEXBOT_LOCALIZED { \
    14003, \
    "HEXBOT_LOCALIZED", \
    4, \
    {  { "side", NULL, MAVLINK_TYPE_UINT8_T, 0, 0, offsetof(mavlink_hexbot_localized_t, side) }, \
         { "yref", NULL, MAVLINK_TYPE_UINT8_T, 0, 1, offsetof(mavlink_hexbot_localized_t, yref) }, \
         { "x", NULL, MAVLINK_TYPE_INT8_T, 0, 2, offsetof(mavlink_hexbot_localized_t, x) }, \
         { "y", NULL, MAVLINK_TYPE_INT8_T, 0, 3, offsetof(mavlink_hexbot_localized_t, y) }, \
         } \
}
#else
#define MAVLINK_MESSAGE_INFO_HEXBOT_LOCALIZED { \
    "HEXBOT_LOCALIZED", \
    4, \
    {  { "side", NULL, MAVLINK_TYPE_UINT8_T, 0, 0, offsetof(mavlink_hexbot_localized_t, side) }, \
         { "yref", NULL, MAVLINK_TYPE_UINT8_T, 0, 1, offsetof(mavlink_hexbot_localized_t, yref) }, \
         { "x", NULL, MAVLINK_TYPE_INT8_T, 0, 2, offsetof(mavlink_hexbot_localized_t, x) }, \
         { "y", NULL, MAVLINK_TYPE_INT8_T, 0, 3, offsetof(mavlink_hexbot_localized_t, y) }, \
         } \
}
#endif

/**
 * @brief Pack a hexbot_localized message
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param msg The MAVLink message to compress the data into
 *
 * @param side  Global side 1..6 the neighbour's message came through.
 * @param yref  Orientation 0..5.
 * @param x  Cell x.
 * @param y  Cell y.
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_hexbot_localized_pack(uint8_t system_id, uint8_t component_id, mavlink_message_t* msg,
                               uint8_t side, uint8_t yref, int8_t x, int8_t y)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_HEXBOT_LOCALIZED_LEN];
    _mav_put_uint8_t(buf, 0, side);
    _mav_put_uint8_t(buf, 1, yref);
    _mav_put_int8_t(buf, 2, x);
    _mav_put_int8_t(buf, 3, y);

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_HEXBOT_LOCALIZED_LEN);
#else
    mavlink_hexbot_localized_t packet;
    packet.side = side;
    packet.yref = yref;
    packet.x = x;
    packet.y = y;

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_HEXBOT_LOCALIZED_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_HEXBOT_LOCALIZED;
    return mavlink_finalize_message(msg, system_id, component_id, MAVLINK_MSG_ID_HEXBOT_LOCALIZED_MIN_LEN, MAVLINK_MSG_ID_HEXBOT_LOCALIZED_LEN, MAVLINK_MSG_ID_HEXBOT_LOCALIZED_CRC);
}

/**
 * @brief Pack a hexbot_localized message
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param status MAVLink status structure
 * @param msg The MAVLink message to compress the data into
 *
 * @param side  Global side 1..6 the neighbour's message came through.
 * @param yref  Orientation 0..5.
 * @param x  Cell x.
 * @param y  Cell y.
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_hexbot_localized_pack_status(uint8_t system_id, uint8_t component_id, mavlink_status_t *_status, mavlink_message_t* msg,
                               uint8_t side, uint8_t yref, int8_t x, int8_t y)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_HEXBOT_LOCALIZED_LEN];
    _mav_put_uint8_t(buf, 0, side);
    _mav_put_uint8_t(buf, 1, yref);
    _mav_put_int8_t(buf, 2, x);
    _mav_put_int8_t(buf, 3, y);

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_HEXBOT_LOCALIZED_LEN);
#else
    mavlink_hexbot_localized_t packet;
    packet.side = side;
    packet.yref = yref;
    packet.x = x;
    packet.y = y;

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_HEXBOT_LOCALIZED_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_HEXBOT_LOCALIZED;
#if MAVLINK_CRC_EXTRA
    return mavlink_finalize_message_buffer(msg, system_id, component_id, _status, MAVLINK_MSG_ID_HEXBOT_LOCALIZED_MIN_LEN, MAVLINK_MSG_ID_HEXBOT_LOCALIZED_LEN, MAVLINK_MSG_ID_HEXBOT_LOCALIZED_CRC);
#else
    return mavlink_finalize_message_buffer(msg, system_id, component_id, _status, MAVLINK_MSG_ID_HEXBOT_LOCALIZED_MIN_LEN, MAVLINK_MSG_ID_HEXBOT_LOCALIZED_LEN);
#endif
}

/**
 * @brief Pack a hexbot_localized message on a channel
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param chan The MAVLink channel this message will be sent over
 * @param msg The MAVLink message to compress the data into
 * @param side  Global side 1..6 the neighbour's message came through.
 * @param yref  Orientation 0..5.
 * @param x  Cell x.
 * @param y  Cell y.
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_hexbot_localized_pack_chan(uint8_t system_id, uint8_t component_id, uint8_t chan,
                               mavlink_message_t* msg,
                                   uint8_t side,uint8_t yref,int8_t x,int8_t y)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_HEXBOT_LOCALIZED_LEN];
    _mav_put_uint8_t(buf, 0, side);
    _mav_put_uint8_t(buf, 1, yref);
    _mav_put_int8_t(buf, 2, x);
    _mav_put_int8_t(buf, 3, y);

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_HEXBOT_LOCALIZED_LEN);
#else
    mavlink_hexbot_localized_t packet;
    packet.side = side;
    packet.yref = yref;
    packet.x = x;
    packet.y = y;

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_HEXBOT_LOCALIZED_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_HEXBOT_LOCALIZED;
    return mavlink_finalize_message_chan(msg, system_id, component_id, chan, MAVLINK_MSG_ID_HEXBOT_LOCALIZED_MIN_LEN, MAVLINK_MSG_ID_HEXBOT_LOCALIZED_LEN, MAVLINK_MSG_ID_HEXBOT_LOCALIZED_CRC);
}

/**
 * @brief Encode a hexbot_localized struct
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param msg The MAVLink message to compress the data into
 * @param hexbot_localized C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_hexbot_localized_encode(uint8_t system_id, uint8_t component_id, mavlink_message_t* msg, const mavlink_hexbot_localized_t* hexbot_localized)
{
    return mavlink_msg_hexbot_localized_pack(system_id, component_id, msg, hexbot_localized->side, hexbot_localized->yref, hexbot_localized->x, hexbot_localized->y);
}

/**
 * @brief Encode a hexbot_localized struct on a channel
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param chan The MAVLink channel this message will be sent over
 * @param msg The MAVLink message to compress the data into
 * @param hexbot_localized C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_hexbot_localized_encode_chan(uint8_t system_id, uint8_t component_id, uint8_t chan, mavlink_message_t* msg, const mavlink_hexbot_localized_t* hexbot_localized)
{
    return mavlink_msg_hexbot_localized_pack_chan(system_id, component_id, chan, msg, hexbot_localized->side, hexbot_localized->yref, hexbot_localized->x, hexbot_localized->y);
}

/**
 * @brief Encode a hexbot_localized struct with provided status structure
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param status MAVLink status structure
 * @param msg The MAVLink message to compress the data into
 * @param hexbot_localized C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_hexbot_localized_encode_status(uint8_t system_id, uint8_t component_id, mavlink_status_t* _status, mavlink_message_t* msg, const mavlink_hexbot_localized_t* hexbot_localized)
{
    return mavlink_msg_hexbot_localized_pack_status(system_id, component_id, _status, msg,  hexbot_localized->side, hexbot_localized->yref, hexbot_localized->x, hexbot_localized->y);
}

/**
 * @brief Send a hexbot_localized message
 * @param chan MAVLink channel to send the message
 *
 * @param side  Global side 1..6 the neighbour's message came through.
 * @param yref  Orientation 0..5.
 * @param x  Cell x.
 * @param y  Cell y.
 */
#ifdef MAVLINK_USE_CONVENIENCE_FUNCTIONS

static inline void mavlink_msg_hexbot_localized_send(mavlink_channel_t chan, uint8_t side, uint8_t yref, int8_t x, int8_t y)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_HEXBOT_LOCALIZED_LEN];
    _mav_put_uint8_t(buf, 0, side);
    _mav_put_uint8_t(buf, 1, yref);
    _mav_put_int8_t(buf, 2, x);
    _mav_put_int8_t(buf, 3, y);

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_HEXBOT_LOCALIZED, buf, MAVLINK_MSG_ID_HEXBOT_LOCALIZED_MIN_LEN, MAVLINK_MSG_ID_HEXBOT_LOCALIZED_LEN, MAVLINK_MSG_ID_HEXBOT_LOCALIZED_CRC);
#else
    mavlink_hexbot_localized_t packet;
    packet.side = side;
    packet.yref = yref;
    packet.x = x;
    packet.y = y;

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_HEXBOT_LOCALIZED, (const char *)&packet, MAVLINK_MSG_ID_HEXBOT_LOCALIZED_MIN_LEN, MAVLINK_MSG_ID_HEXBOT_LOCALIZED_LEN, MAVLINK_MSG_ID_HEXBOT_LOCALIZED_CRC);
#endif
}

/**
 * @brief Send a hexbot_localized message
 * @param chan MAVLink channel to send the message
 * @param struct The MAVLink struct to serialize
 */
static inline void mavlink_msg_hexbot_localized_send_struct(mavlink_channel_t chan, const mavlink_hexbot_localized_t* hexbot_localized)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    mavlink_msg_hexbot_localized_send(chan, hexbot_localized->side, hexbot_localized->yref, hexbot_localized->x, hexbot_localized->y);
#else
    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_HEXBOT_LOCALIZED, (const char *)hexbot_localized, MAVLINK_MSG_ID_HEXBOT_LOCALIZED_MIN_LEN, MAVLINK_MSG_ID_HEXBOT_LOCALIZED_LEN, MAVLINK_MSG_ID_HEXBOT_LOCALIZED_CRC);
#endif
}

#if MAVLINK_MSG_ID_HEXBOT_LOCALIZED_LEN <= MAVLINK_MAX_PAYLOAD_LEN
/*
  This variant of _send() can be used to save stack space by reusing
  memory from the receive buffer.  The caller provides a
  mavlink_message_t which is the size of a full mavlink message. This
  is usually the receive buffer for the channel, and allows a reply to an
  incoming message with minimum stack space usage.
 */
static inline void mavlink_msg_hexbot_localized_send_buf(mavlink_message_t *msgbuf, mavlink_channel_t chan,  uint8_t side, uint8_t yref, int8_t x, int8_t y)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char *buf = (char *)msgbuf;
    _mav_put_uint8_t(buf, 0, side);
    _mav_put_uint8_t(buf, 1, yref);
    _mav_put_int8_t(buf, 2, x);
    _mav_put_int8_t(buf, 3, y);

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_HEXBOT_LOCALIZED, buf, MAVLINK_MSG_ID_HEXBOT_LOCALIZED_MIN_LEN, MAVLINK_MSG_ID_HEXBOT_LOCALIZED_LEN, MAVLINK_MSG_ID_HEXBOT_LOCALIZED_CRC);
#else
    mavlink_hexbot_localized_t *packet = (mavlink_hexbot_localized_t *)msgbuf;
    packet->side = side;
    packet->yref = yref;
    packet->x = x;
    packet->y = y;

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_HEXBOT_LOCALIZED, (const char *)packet, MAVLINK_MSG_ID_HEXBOT_LOCALIZED_MIN_LEN, MAVLINK_MSG_ID_HEXBOT_LOCALIZED_LEN, MAVLINK_MSG_ID_HEXBOT_LOCALIZED_CRC);
#endif
}
#endif

#endif

// MESSAGE HEXBOT_LOCALIZED UNPACKING


/**
 * @brief Get field side from hexbot_localized message
 *
 * @return  Global side 1..6 the neighbour's message came through.
 */
static inline uint8_t mavlink_msg_hexbot_localized_get_side(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint8_t(msg,  0);
}

/**
 * @brief Get field yref from hexbot_localized message
 *
 * @return  Orientation 0..5.
 */
static inline uint8_t mavlink_msg_hexbot_localized_get_yref(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint8_t(msg,  1);
}

/**
 * @brief Get field x from hexbot_localized message
 *
 * @return  Cell x.
 */
static inline int8_t mavlink_msg_hexbot_localized_get_x(const mavlink_message_t* msg)
{
    return _MAV_RETURN_int8_t(msg,  2);
}

/**
 * @brief Get field y from hexbot_localized message
 *
 * @return  Cell y.
 */
static inline int8_t mavlink_msg_hexbot_localized_get_y(const mavlink_message_t* msg)
{
    return _MAV_RETURN_int8_t(msg,  3);
}

/**
 * @brief Decode a hexbot_localized message into a struct
 *
 * @param msg The message to decode
 * @param hexbot_localized C-struct to decode the message contents into
 */
static inline void mavlink_msg_hexbot_localized_decode(const mavlink_message_t* msg, mavlink_hexbot_localized_t* hexbot_localized)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    hexbot_localized->side = mavlink_msg_hexbot_localized_get_side(msg);
    hexbot_localized->yref = mavlink_msg_hexbot_localized_get_yref(msg);
    hexbot_localized->x = mavlink_msg_hexbot_localized_get_x(msg);
    hexbot_localized->y = mavlink_msg_hexbot_localized_get_y(msg);
#else
        uint8_t len = msg->len < MAVLINK_MSG_ID_HEXBOT_LOCALIZED_LEN? msg->len : MAVLINK_MSG_ID_HEXBOT_LOCALIZED_LEN;
        memset(hexbot_localized, 0, MAVLINK_MSG_ID_HEXBOT_LOCALIZED_LEN);
    memcpy(hexbot_localized, _MAV_PAYLOAD(msg), len);
#endif
}
