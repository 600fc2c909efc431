#pragma once
// MESSAGE HEXBOT_ACK PACKING

#include <stdint.h>

#define MAVLINK_MSG_ID_HEXBOT_ACK 14001


typedef struct __mavlink_hexbot_ack_t {
 uint8_t code; /*<  Code of the command answered.*/
 uint8_t role; /*<  The module's role.*/
 uint8_t result; /*<  What happened.*/
 uint8_t error; /*<  Error reason when result is ERROR.*/
} mavlink_hexbot_ack_t;

#define MAVLINK_MSG_ID_HEXBOT_ACK_LEN 4
#define MAVLINK_MSG_ID_HEXBOT_ACK_MIN_LEN 4
#define MAVLINK_MSG_ID_14001_LEN 4
#define MAVLINK_MSG_ID_14001_MIN_LEN 4

#define MAVLINK_MSG_ID_HEXBOT_ACK_CRC 87
#define MAVLINK_MSG_ID_14001_CRC 87



#if MAVLINK_COMMAND_24BIT
#define MAVLINK_MESSAGE_INFO_HEXBOT_ACK { \
    14001, \
    "HEXBOT_ACK", \
    4, \
    {  { "code", NULL, MAVLINK_TYPE_UINT8_T, 0, 0, offsetof(mavlink_hexbot_ack_t, code) }, \
         { "role", NULL, MAVLINK_TYPE_UINT8_T, 0, 1, offsetof(mavlink_hexbot_ack_t, role) }, \
         { "result", NULL, MAVLINK_TYPE_UINT8_T, 0, 2, offsetof(mavlink_hexbot_ack_t, result) }, \
         { "error", NULL, MAVLINK_TYPE_UINT8_T, 0, 3, offsetof(mavlink_hexbot_ack_t, error) }, \
         } \
}
#else
#define MAVLINK_MESSAGE_INFO_HEXBOT_ACK { \
    "HEXBOT_ACK", \
    4, \
    {  { "code", NULL, MAVLINK_TYPE_UINT8_T, 0, 0, offsetof(mavlink_hexbot_ack_t, code) }, \
         { "role", NULL, MAVLINK_TYPE_UINT8_T, 0, 1, offsetof(mavlink_hexbot_ack_t, role) }, \
         { "result", NULL, MAVLINK_TYPE_UINT8_T, 0, 2, offsetof(mavlink_hexbot_ack_t, result) }, \
         { "error", NULL, MAVLINK_TYPE_UINT8_T, 0, 3, offsetof(mavlink_hexbot_ack_t, error) }, \
         } \
}
#endif

/**
 * @brief Pack a hexbot_ack message
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param msg The MAVLink message to compress the data into
 *
 * @param code  Code of the command answered.
 * @param role  The module's role.
 * @param result  What happened.
 * @param error  Error reason when result is ERROR.
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_hexbot_ack_pack(uint8_t system_id, uint8_t component_id, mavlink_message_t* msg,
                               uint8_t code, uint8_t role, uint8_t result, uint8_t error)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_HEXBOT_ACK_LEN];
    _mav_put_uint8_t(buf, 0, code);
    _mav_put_uint8_t(buf, 1, role);
    _mav_put_uint8_t(buf, 2, result);
    _mav_put_uint8_t(buf, 3, error);

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_HEXBOT_ACK_LEN);
#else
    mavlink_hexbot_ack_t packet;
    packet.code = code;
    packet.role = role;
    packet.result = result;
    packet.error = error;

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_HEXBOT_ACK_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_HEXBOT_ACK;
    return mavlink_finalize_message(msg, system_id, component_id, MAVLINK_MSG_ID_HEXBOT_ACK_MIN_LEN, MAVLINK_MSG_ID_HEXBOT_ACK_LEN, MAVLINK_MSG_ID_HEXBOT_ACK_CRC);
}

/**
 * @brief Pack a hexbot_ack message
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param status MAVLink status structure
 * @param msg The MAVLink message to compress the data into
 *
 * @param code  Code of the command answered.
 * @param role  The module's role.
 * @param result  What happened.
 * @param error  Error reason when result is ERROR.
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_hexbot_ack_pack_status(uint8_t system_id, uint8_t component_id, mavlink_status_t *_status, mavlink_message_t* msg,
                               uint8_t code, uint8_t role, uint8_t result, uint8_t error)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_HEXBOT_ACK_LEN];
    _mav_put_uint8_t(buf, 0, code);
    _mav_put_uint8_t(buf, 1, role);
    _mav_put_uint8_t(buf, 2, result);
    _mav_put_uint8_t(buf, 3, error);

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_HEXBOT_ACK_LEN);
#else
    mavlink_hexbot_ack_t packet;
    packet.code = code;
    packet.role = role;
    packet.result = result;
    packet.error = error;

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_HEXBOT_ACK_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_HEXBOT_ACK;
#if MAVLINK_CRC_EXTRA
    return mavlink_finalize_message_buffer(msg, system_id, component_id, _status, MAVLINK_MSG_ID_HEXBOT_ACK_MIN_LEN, MAVLINK_MSG_ID_HEXBOT_ACK_LEN, MAVLINK_MSG_ID_HEXBOT_ACK_CRC);
#else
    return mavlink_finalize_message_buffer(msg, system_id, component_id, _status, MAVLINK_MSG_ID_HEXBOT_ACK_MIN_LEN, MAVLINK_MSG_ID_HEXBOT_ACK_LEN);
#endif
}

/**
 * @brief Pack a hexbot_ack message on a channel
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param chan The MAVLink channel this message will be sent over
 * @param msg The MAVLink message to compress the data into
 * @param code  Code of the command answered.
 * @param role  The module's role.
 * @param result  What happened.
 * @param error  Error reason when result is ERROR.
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_hexbot_ack_pack_chan(uint8_t system_id, uint8_t component_id, uint8_t chan,
                               mavlink_message_t* msg,
                                   uint8_t code,uint8_t role,uint8_t result,uint8_t error)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_HEXBOT_ACK_LEN];
    _mav_put_uint8_t(buf, 0, code);
    _mav_put_uint8_t(buf, 1, role);
    _mav_put_uint8_t(buf, 2, result);
    _mav_put_uint8_t(buf, 3, error);

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_HEXBOT_ACK_LEN);
#else
    mavlink_hexbot_ack_t packet;
    packet.code = code;
    packet.role = role;
    packet.result = result;
    packet.error = error;

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_HEXBOT_ACK_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_HEXBOT_ACK;
    return mavlink_finalize_message_chan(msg, system_id, component_id, chan, MAVLINK_MSG_ID_HEXBOT_ACK_MIN_LEN, MAVLINK_MSG_ID_HEXBOT_ACK_LEN, MAVLINK_MSG_ID_HEXBOT_ACK_CRC);
}

/**
 * @brief Encode a hexbot_ack struct
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param msg The MAVLink message to compress the data into
 * @param hexbot_ack C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_hexbot_ack_encode(uint8_t system_id, uint8_t component_id, mavlink_message_t* msg, const mavlink_hexbot_ack_t* hexbot_ack)
{
    return mavlink_msg_hexbot_ack_pack(system_id, component_id, msg, hexbot_ack->code, hexbot_ack->role, hexbot_ack->result, hexbot_ack->error);
}

/**
 * @brief Encode a hexbot_ack struct on a channel
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param chan The MAVLink channel this message will be sent over
 * @param msg The MAVLink message to compress the data into
 * @param hexbot_ack C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_hexbot_ack_encode_chan(uint8_t system_id, uint8_t component_id, uint8_t chan, mavlink_message_t* msg, const mavlink_hexbot_ack_t* hexbot_ack)
{
    return mavlink_msg_hexbot_ack_pack_chan(system_id, component_id, chan, msg, hexbot_ack->code, hexbot_ack->role, hexbot_ack->result, hexbot_ack->error);
}

/**
 * @brief Encode a hexbot_ack struct with provided status structure
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param status MAVLink status structure
 * @param msg The MAVLink message to compress the data into
 * @param hexbot_ack C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_hexbot_ack_encode_status(uint8_t system_id, uint8_t component_id, mavlink_status_t* _status, mavlink_message_t* msg, const mavlink_hexbot_ack_t* hexbot_ack)
{
    return mavlink_msg_hexbot_ack_pack_status(system_id, component_id, _status, msg,  hexbot_ack->code, hexbot_ack->role, hexbot_ack->result, hexbot_ack->error);
}

/**
 * @brief Send a hexbot_ack message
 * @param chan MAVLink channel to send the message
 *
 * @param code  Code of the command answered.
 * @param role  The module's role.
 * @param result  What happened.
 * @param error  Error reason when result is ERROR.
 */
#ifdef MAVLINK_USE_CONVENIENCE_FUNCTIONS

static inline void mavlink_msg_hexbot_ack_send(mavlink_channel_t chan, uint8_t code, uint8_t role, uint8_t result, uint8_t error)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_HEXBOT_ACK_LEN];
    _mav_put_uint8_t(buf, 0, code);
    _mav_put_uint8_t(buf, 1, role);
    _mav_put_uint8_t(buf, 2, result);
    _mav_put_uint8_t(buf, 3, error);

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_HEXBOT_ACK, buf, MAVLINK_MSG_ID_HEXBOT_ACK_MIN_LEN, MAVLINK_MSG_ID_HEXBOT_ACK_LEN, MAVLINK_MSG_ID_HEXBOT_ACK_CRC);
#else
    mavlink_hexbot_ack_t packet;
    packet.code = code;
    packet.role = role;
    packet.result = result;
    packet.error = error;

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_HEXBOT_ACK, (const char *)&packet, MAVLINK_MSG_ID_HEXBOT_ACK_MIN_LEN, MAVLINK_MSG_ID_HEXBOT_ACK_LEN, MAVLINK_MSG_ID_HEXBOT_ACK_CRC);
#endif
}

/**
 * @brief Send a hexbot_ack message
 * @param chan MAVLink channel to send the message
 * @param struct The MAVLink struct to serialize
 */
static inline void mavlink_msg_hexbot_ack_send_struct(mavlink_channel_t chan, const mavlink_hexbot_ack_t* hexbot_ack)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    mavlink_msg_hexbot_ack_send(chan, hexbot_ack->code, hexbot_ack->role, hexbot_ack->result, hexbot_ack->error);
#else
    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_HEXBOT_ACK, (const char *)hexbot_ack, MAVLINK_MSG_ID_HEXBOT_ACK_MIN_LEN, MAVLINK_MSG_ID_HEXBOT_ACK_LEN, MAVLINK_MSG_ID_HEXBOT_ACK_CRC);
#endif
}

#if MAVLINK_MSG_ID_HEXBOT_ACK_LEN <= MAVLINK_MAX_PAYLOAD_LEN
/*
  This variant of _send() can be used to save stack space by reusing
  memory from the receive buffer.  The caller provides a
  mavlink_message_t which is the size of a full mavlink message. This
  is usually the receive buffer for the channel, and allows a reply to an
  incoming message with minimum stack space usage.
 */
static inline void mavlink_msg_hexbot_ack_send_buf(mavlink_message_t *msgbuf, mavlink_channel_t chan,  uint8_t code, uint8_t role, uint8_t result, uint8_t error)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char *buf = (char *)msgbuf;
    _mav_put_uint8_t(buf, 0, code);
    _mav_put_uint8_t(buf, 1, role);
    _mav_put_uint8_t(buf, 2, result);
    _mav_put_uint8_t(buf, 3, error);

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_HEXBOT_ACK, buf, MAVLINK_MSG_ID_HEXBOT_ACK_MIN_LEN, MAVLINK_MSG_ID_HEXBOT_ACK_LEN, MAVLINK_MSG_ID_HEXBOT_ACK_CRC);
#else
    mavlink_hexbot_ack_t *packet = (mavlink_hexbot_ack_t *)msgbuf;
    packet->code = code;
    packet->role = role;
    packet->result = result;
    packet->error = error;

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_HEXBOT_ACK, (const char *)packet, MAVLINK_MSG_ID_HEXBOT_ACK_MIN_LEN, MAVLINK_MSG_ID_HEXBOT_ACK_LEN, MAVLINK_MSG_ID_HEXBOT_ACK_CRC);
#endif
}
#endif

#endif

// MESSAGE HEXBOT_ACK UNPACKING


/**
 * @brief Get field code from hexbot_ack message
 *
 * @return  Code of the command answered.
 */
static inline uint8_t mavlink_msg_hexbot_ack_get_code(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint8_t(msg,  0);
}

/**
 * @brief Get field role from hexbot_ack message
 *
 * @return  The module's role.
 */
static inline uint8_t mavlink_msg_hexbot_ack_get_role(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint8_t(msg,  1);
}

/**
 * @brief Get field result from hexbot_ack message
 *
 * @return  What happened.
 */
static inline uint8_t mavlink_msg_hexbot_ack_get_result(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint8_t(msg,  2);
}

/**
 * @brief Get field error from hexbot_ack message
 *
 * @return  Error reason when result is ERROR.
 */
static inline uint8_t mavlink_msg_hexbot_ack_get_error(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint8_t(msg,  3);
}

/**
 * @brief Decode a hexbot_ack message into a struct
 *
 * @param msg The message to decode
 * @param hexbot_ack C-struct to decode the message contents into
 */
static inline void mavlink_msg_hexbot_ack_decode(const mavlink_message_t* msg, mavlink_hexbot_ack_t* hexbot_ack)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    hexbot_ack->code = mavlink_msg_hexbot_ack_get_code(msg);
    hexbot_ack->role = mavlink_msg_hexbot_ack_get_role(msg);
    hexbot_ack->result = mavlink_msg_hexbot_ack_get_result(msg);
    hexbot_ack->error = mavlink_msg_hexbot_ack_get_error(msg);
#else
        uint8_t len = msg->len < MAVLINK_MSG_ID_HEXBOT_ACK_LEN? msg->len : MAVLINK_MSG_ID_HEXBOT_ACK_LEN;
        memset(hexbot_ack, 0, MAVLINK_MSG_ID_HEXBOT_ACK_LEN);
    memcpy(hexbot_ack, _MAV_PAYLOAD(msg), len);
#endif
}
