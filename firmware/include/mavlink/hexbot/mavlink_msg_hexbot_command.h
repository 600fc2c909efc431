#pragma once
// MESSAGE HEXBOT_COMMAND PACKING

#include <stdint.h>

#define MAVLINK_MSG_ID_HEXBOT_COMMAND 14000


typedef struct __mavlink_hexbot_command_t {
 uint8_t target_system; /*<  Module id (DIP switches, 1..255); 0 = the modules the last Select chose (all after Select(0)), as a legacy frame.*/
 uint8_t code; /*<  Function code (B1).*/
 uint8_t args[8]; /*<  Argument bytes B2..B9; unused ones 0.*/
} mavlink_hexbot_command_t;

#define MAVLINK_MSG_ID_HEXBOT_COMMAND_LEN 10
#define MAVLINK_MSG_ID_HEXBOT_COMMAND_MIN_LEN 10
#define MAVLINK_MSG_ID_14000_LEN 10
#define MAVLINK_MSG_ID_14000_MIN_LEN 10

#define MAVLINK_MSG_ID_HEXBOT_COMMAND_CRC 229
#define MAVLINK_MSG_ID_14000_CRC 229

#define MAVLINK_MSG_HEXBOT_COMMAND_FIELD_ARGS_LEN 8

#if MAVLINK_COMMAND_24BIT
#define MAVLINK_MESSAGE_INFO_HEXBOT_COMMAND { \
    14000, \
    "HEXBOT_COMMAND", \
    3, \
    {  { "target_system", NULL, MAVLINK_TYPE_UINT8_T, 0, 0, offsetof(mavlink_hexbot_command_t, target_system) }, \
         { "code", NULL, MAVLINK_TYPE_UINT8_T, 0, 1, offsetof(mavlink_hexbot_command_t, code) }, \
         { "args", NULL, MAVLINK_TYPE_UINT8_T, 8, 2, offsetof(mavlink_hexbot_command_t, args) }, \
         } \
}
#else
#define MAVLINK_MESSAGE_INFO_HEXBOT_COMMAND { \
    "HEXBOT_COMMAND", \
    3, \
    {  { "target_system", NULL, MAVLINK_TYPE_UINT8_T, 0, 0, offsetof(mavlink_hexbot_command_t, target_system) }, \
         { "code", NULL, MAVLINK_TYPE_UINT8_T, 0, 1, offsetof(mavlink_hexbot_command_t, code) }, \
         { "args", NULL, MAVLINK_TYPE_UINT8_T, 8, 2, offsetof(mavlink_hexbot_command_t, args) }, \
         } \
}
#endif

/**
 * @brief Pack a hexbot_command message
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param msg The MAVLink message to compress the data into
 *
 * @param target_system  Module id (DIP switches, 1..255); 0 = the modules the last Select chose (all after Select(0)), as a legacy frame.
 * @param code  Function code (B1).
 * @param args  Argument bytes B2..B9; unused ones 0.
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_hexbot_command_pack(uint8_t system_id, uint8_t component_id, mavlink_message_t* msg,
                               uint8_t target_system, uint8_t code, const uint8_t *args)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_HEXBOT_COMMAND_LEN];
    _mav_put_uint8_t(buf, 0, target_system);
    _mav_put_uint8_t(buf, 1, code);
    _mav_put_uint8_t_array(buf, 2, args, 8);
        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_HEXBOT_COMMAND_LEN);
#else
    mavlink_hexbot_command_t packet;
    packet.target_system = target_system;
    packet.code = code;
    mav_array_memcpy(packet.args, args, sizeof(uint8_t)*8);
        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_HEXBOT_COMMAND_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_HEXBOT_COMMAND;
    return mavlink_finalize_message(msg, system_id, component_id, MAVLINK_MSG_ID_HEXBOT_COMMAND_MIN_LEN, MAVLINK_MSG_ID_HEXBOT_COMMAND_LEN, MAVLINK_MSG_ID_HEXBOT_COMMAND_CRC);
}

/**
 * @brief Pack a hexbot_command message
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param status MAVLink status structure
 * @param msg The MAVLink message to compress the data into
 *
 * @param target_system  Module id (DIP switches, 1..255); 0 = the modules the last Select chose (all after Select(0)), as a legacy frame.
 * @param code  Function code (B1).
 * @param args  Argument bytes B2..B9; unused ones 0.
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_hexbot_command_pack_status(uint8_t system_id, uint8_t component_id, mavlink_status_t *_status, mavlink_message_t* msg,
                               uint8_t target_system, uint8_t code, const uint8_t *args)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_HEXBOT_COMMAND_LEN];
    _mav_put_uint8_t(buf, 0, target_system);
    _mav_put_uint8_t(buf, 1, code);
    _mav_put_uint8_t_array(buf, 2, args, 8);
        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_HEXBOT_COMMAND_LEN);
#else
    mavlink_hexbot_command_t packet;
    packet.target_system = target_system;
    packet.code = code;
    mav_array_memcpy(packet.args, args, sizeof(uint8_t)*8);
        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_HEXBOT_COMMAND_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_HEXBOT_COMMAND;
#if MAVLINK_CRC_EXTRA
    return mavlink_finalize_message_buffer(msg, system_id, component_id, _status, MAVLINK_MSG_ID_HEXBOT_COMMAND_MIN_LEN, MAVLINK_MSG_ID_HEXBOT_COMMAND_LEN, MAVLINK_MSG_ID_HEXBOT_COMMAND_CRC);
#else
    return mavlink_finalize_message_buffer(msg, system_id, component_id, _status, MAVLINK_MSG_ID_HEXBOT_COMMAND_MIN_LEN, MAVLINK_MSG_ID_HEXBOT_COMMAND_LEN);
#endif
}

/**
 * @brief Pack a hexbot_command message on a channel
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param chan The MAVLink channel this message will be sent over
 * @param msg The MAVLink message to compress the data into
 * @param target_system  Module id (DIP switches, 1..255); 0 = the modules the last Select chose (all after Select(0)), as a legacy frame.
 * @param code  Function code (B1).
 * @param args  Argument bytes B2..B9; unused ones 0.
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_hexbot_command_pack_chan(uint8_t system_id, uint8_t component_id, uint8_t chan,
                               mavlink_message_t* msg,
                                   uint8_t target_system,uint8_t code,const uint8_t *args)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_HEXBOT_COMMAND_LEN];
    _mav_put_uint8_t(buf, 0, target_system);
    _mav_put_uint8_t(buf, 1, code);
    _mav_put_uint8_t_array(buf, 2, args, 8);
        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_HEXBOT_COMMAND_LEN);
#else
    mavlink_hexbot_command_t packet;
    packet.target_system = target_system;
    packet.code = code;
    mav_array_memcpy(packet.args, args, sizeof(uint8_t)*8);
        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_HEXBOT_COMMAND_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_HEXBOT_COMMAND;
    return mavlink_finalize_message_chan(msg, system_id, component_id, chan, MAVLINK_MSG_ID_HEXBOT_COMMAND_MIN_LEN, MAVLINK_MSG_ID_HEXBOT_COMMAND_LEN, MAVLINK_MSG_ID_HEXBOT_COMMAND_CRC);
}

/**
 * @brief Encode a hexbot_command struct
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param msg The MAVLink message to compress the data into
 * @param hexbot_command C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_hexbot_command_encode(uint8_t system_id, uint8_t component_id, mavlink_message_t* msg, const mavlink_hexbot_command_t* hexbot_command)
{
    return mavlink_msg_hexbot_command_pack(system_id, component_id, msg, hexbot_command->target_system, hexbot_command->code, hexbot_command->args);
}

/**
 * @brief Encode a hexbot_command struct on a channel
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param chan The MAVLink channel this message will be sent over
 * @param msg The MAVLink message to compress the data into
 * @param hexbot_command C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_hexbot_command_encode_chan(uint8_t system_id, uint8_t component_id, uint8_t chan, mavlink_message_t* msg, const mavlink_hexbot_command_t* hexbot_command)
{
    return mavlink_msg_hexbot_command_pack_chan(system_id, component_id, chan, msg, hexbot_command->target_system, hexbot_command->code, hexbot_command->args);
}

/**
 * @brief Encode a hexbot_command struct with provided status structure
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param status MAVLink status structure
 * @param msg The MAVLink message to compress the data into
 * @param hexbot_command C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_hexbot_command_encode_status(uint8_t system_id, uint8_t component_id, mavlink_status_t* _status, mavlink_message_t* msg, const mavlink_hexbot_command_t* hexbot_command)
{
    return mavlink_msg_hexbot_command_pack_status(system_id, component_id, _status, msg,  hexbot_command->target_system, hexbot_command->code, hexbot_command->args);
}

/**
 * @brief Send a hexbot_command message
 * @param chan MAVLink channel to send the message
 *
 * @param target_system  Module id (DIP switches, 1..255); 0 = the modules the last Select chose (all after Select(0)), as a legacy frame.
 * @param code  Function code (B1).
 * @param args  Argument bytes B2..B9; unused ones 0.
 */
#ifdef MAVLINK_USE_CONVENIENCE_FUNCTIONS

static inline void mavlink_msg_hexbot_command_send(mavlink_channel_t chan, uint8_t target_system, uint8_t code, const uint8_t *args)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_HEXBOT_COMMAND_LEN];
    _mav_put_uint8_t(buf, 0, target_system);
    _mav_put_uint8_t(buf, 1, code);
    _mav_put_uint8_t_array(buf, 2, args, 8);
    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_HEXBOT_COMMAND, buf, MAVLINK_MSG_ID_HEXBOT_COMMAND_MIN_LEN, MAVLINK_MSG_ID_HEXBOT_COMMAND_LEN, MAVLINK_MSG_ID_HEXBOT_COMMAND_CRC);
#else
    mavlink_hexbot_command_t packet;
    packet.target_system = target_system;
    packet.code = code;
    mav_array_memcpy(packet.args, args, sizeof(uint8_t)*8);
    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_HEXBOT_COMMAND, (const char *)&packet, MAVLINK_MSG_ID_HEXBOT_COMMAND_MIN_LEN, MAVLINK_MSG_ID_HEXBOT_COMMAND_LEN, MAVLINK_MSG_ID_HEXBOT_COMMAND_CRC);
#endif
}

/**
 * @brief Send a hexbot_command message
 * @param chan MAVLink channel to send the message
 * @param struct The MAVLink struct to serialize
 */
static inline void mavlink_msg_hexbot_command_send_struct(mavlink_channel_t chan, const mavlink_hexbot_command_t* hexbot_command)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    mavlink_msg_hexbot_command_send(chan, hexbot_command->target_system, hexbot_command->code, hexbot_command->args);
#else
    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_HEXBOT_COMMAND, (const char *)hexbot_command, MAVLINK_MSG_ID_HEXBOT_COMMAND_MIN_LEN, MAVLINK_MSG_ID_HEXBOT_COMMAND_LEN, MAVLINK_MSG_ID_HEXBOT_COMMAND_CRC);
#endif
}

#if MAVLINK_MSG_ID_HEXBOT_COMMAND_LEN <= MAVLINK_MAX_PAYLOAD_LEN
/*
  This variant of _send() can be used to save stack space by reusing
  memory from the receive buffer.  The caller provides a
  mavlink_message_t which is the size of a full mavlink message. This
  is usually the receive buffer for the channel, and allows a reply to an
  incoming message with minimum stack space usage.
 */
static inline void mavlink_msg_hexbot_command_send_buf(mavlink_message_t *msgbuf, mavlink_channel_t chan,  uint8_t target_system, uint8_t code, const uint8_t *args)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char *buf = (char *)msgbuf;
    _mav_put_uint8_t(buf, 0, target_system);
    _mav_put_uint8_t(buf, 1, code);
    _mav_put_uint8_t_array(buf, 2, args, 8);
    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_HEXBOT_COMMAND, buf, MAVLINK_MSG_ID_HEXBOT_COMMAND_MIN_LEN, MAVLINK_MSG_ID_HEXBOT_COMMAND_LEN, MAVLINK_MSG_ID_HEXBOT_COMMAND_CRC);
#else
    mavlink_hexbot_command_t *packet = (mavlink_hexbot_command_t *)msgbuf;
    packet->target_system = target_system;
    packet->code = code;
    mav_array_memcpy(packet->args, args, sizeof(uint8_t)*8);
    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_HEXBOT_COMMAND, (const char *)packet, MAVLINK_MSG_ID_HEXBOT_COMMAND_MIN_LEN, MAVLINK_MSG_ID_HEXBOT_COMMAND_LEN, MAVLINK_MSG_ID_HEXBOT_COMMAND_CRC);
#endif
}
#endif

#endif

// MESSAGE HEXBOT_COMMAND UNPACKING


/**
 * @brief Get field target_system from hexbot_command message
 *
 * @return  Module id (DIP switches, 1..255); 0 = the modules the last Select chose (all after Select(0)), as a legacy frame.
 */
static inline uint8_t mavlink_msg_hexbot_command_get_target_system(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint8_t(msg,  0);
}

/**
 * @brief Get field code from hexbot_command message
 *
 * @return  Function code (B1).
 */
static inline uint8_t mavlink_msg_hexbot_command_get_code(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint8_t(msg,  1);
}

/**
 * @brief Get field args from hexbot_command message
 *
 * @return  Argument bytes B2..B9; unused ones 0.
 */
static inline uint16_t mavlink_msg_hexbot_command_get_args(const mavlink_message_t* msg, uint8_t *args)
{
    return _MAV_RETURN_uint8_t_array(msg, args, 8,  2);
}

/**
 * @brief Decode a hexbot_command message into a struct
 *
 * @param msg The message to decode
 * @param hexbot_command C-struct to decode the message contents into
 */
static inline void mavlink_msg_hexbot_command_decode(const mavlink_message_t* msg, mavlink_hexbot_command_t* hexbot_command)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    hexbot_command->target_system = mavlink_msg_hexbot_command_get_target_system(msg);
    hexbot_command->code = mavlink_msg_hexbot_command_get_code(msg);
    mavlink_msg_hexbot_command_get_args(msg, hexbot_command->args);
#else
        uint8_t len = msg->len < MAVLINK_MSG_ID_HEXBOT_COMMAND_LEN? msg->len : MAVLINK_MSG_ID_HEXBOT_COMMAND_LEN;
        memset(hexbot_command, 0, MAVLINK_MSG_ID_HEXBOT_COMMAND_LEN);
    memcpy(hexbot_command, _MAV_PAYLOAD(msg), len);
#endif
}
