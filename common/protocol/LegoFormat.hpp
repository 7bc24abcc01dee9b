#pragma once
#include <cstddef>
#include <cstdint>

// LEGO's direct and system commands as the brick serves them: opcodes, reply status codes and the
// byte sizes of each served command and reply (LEGO Mindstorms NXT Bluetooth Developer Kit,
// appendices 1 and 2). A telegram is [type][opcode][...]; every multi-byte field little-endian.
namespace nxtmap::protocol {

// Direct commands (type 0x00 / 0x80).
constexpr uint8_t kLegoPlayTone = 0x03;            // [freq Hz u16][duration ms u16]
constexpr uint8_t kLegoSetOutputState = 0x04;      // [port][power s8][mode][regulation][turn s8][run state][limit u32]
constexpr uint8_t kLegoGetOutputState = 0x06;      // [port]
constexpr uint8_t kLegoGetInputValues = 0x07;      // [port]
constexpr uint8_t kLegoMessageWrite = 0x09;        // [inbox][size][size bytes, NUL last]
constexpr uint8_t kLegoResetMotorPosition = 0x0A;  // [port][relative]
constexpr uint8_t kLegoGetBatteryLevel = 0x0B;
constexpr uint8_t kLegoStopSoundPlayback = 0x0C;
constexpr uint8_t kLegoKeepAlive = 0x0D;
constexpr uint8_t kLegoMessageRead = 0x13;  // [remote inbox][local inbox][remove]
// System commands (type 0x01 / 0x81).
constexpr uint8_t kLegoGetFirmwareVersion = 0x88;
constexpr uint8_t kLegoSetBrickName = 0x98;  // [name: 15 bytes, or 15 + NUL]
constexpr uint8_t kLegoGetDeviceInfo = 0x9B;

// Reply status codes (byte 2 of every reply).
constexpr uint8_t kLegoOk = 0x00;
constexpr uint8_t kLegoMailboxEmpty = 0x40;     // "specified mailbox queue is empty"
constexpr uint8_t kLegoRequestFailed = 0xBD;    // "request failed": refused (e.g. motors busy)
constexpr uint8_t kLegoUnknownCommand = 0xBE;   // "unknown command opcode"
constexpr uint8_t kLegoInsanePacket = 0xBF;     // "insane packet": a served opcode of the wrong size
constexpr uint8_t kLegoOutOfRange = 0xC0;       // "data contains out-of-range values"
constexpr uint8_t kLegoNoActiveProgram = 0xEC;  // "no active program" (never: the brick always runs nxtmap)
constexpr uint8_t kLegoIllegalMailbox = 0xEE;   // "illegal mailbox queue ID specified"
constexpr uint8_t kLegoNoMemory = 0xFB;         // "insufficient memory available"

// LEGO's message queues: 20 (0..9 the inboxes a PC writes, 10..19 by convention a program's
// outboxes), 5 messages each, messages of up to 59 bytes including the terminating NUL.
constexpr uint8_t kLegoMailboxes = 20;
constexpr uint8_t kLegoMessagesPerBox = 5;
constexpr uint8_t kLegoMaxMessage = 59;
// Ports: outputs A..C (0..2; SET_OUTPUT_STATE also takes 0xFF = all), inputs 1..4 (0..3).
constexpr uint8_t kLegoOutputs = 3;
constexpr uint8_t kLegoAllOutputs = 0xFF;
constexpr uint8_t kLegoInputs = 4;
constexpr size_t kLegoNameChars = 15;  // brick name, without its NUL

// Telegram sizes of the served commands (0: variable) and of their replies.
constexpr size_t kLegoBatteryCommandSize = 2, kLegoBatteryReplySize = 5;      // [02][0B][st][mV u16]
constexpr size_t kLegoKeepAliveCommandSize = 2, kLegoKeepAliveReplySize = 7;  // [02][0D][st][ms u32]
constexpr size_t kLegoReadCommandSize = 5, kLegoReadReplySize = 64;           // [02][13][st][box][len][59]
constexpr size_t kLegoWriteReplySize = 3;                                     // [02][09][st]
constexpr size_t kLegoStatusReplySize = 3;                                    // [02][op][st]
constexpr size_t kLegoOutputStateReplySize = 25;  // [02][06][st][port][power]...[rotation count s32]
constexpr size_t kLegoInputValuesReplySize = 16;  // [02][07][st][port][valid]...[calibrated s16]
constexpr size_t kLegoVersionReplySize = 7;       // [02][88][st][prot minor][prot major][fw minor][fw major]
constexpr size_t kLegoDeviceInfoReplySize = 33;   // [02][9B][st][name 15][address 7][signal 4][free flash u32]
// The versions GET_FIRMWARE_VERSION reports: LEGO's protocol 1.124 (the layouts above, as LEGO's
// firmware 1.29 reports), and the nxtmap firmware as major 0, minor kProtocolVersion (major 0: not
// LEGO's firmware). nxt-python (nxt/brick.py get_firmware_version) reads the four bytes and checks
// none of them; its nxt-test and nxt_filer only print them.
constexpr uint8_t kLegoProtocolMajor = 1, kLegoProtocolMinor = 124;

// Output modes and run states (GET/SET_OUTPUT_STATE).
constexpr uint8_t kLegoMotorOn = 0x01, kLegoBrake = 0x02, kLegoRegulated = 0x04;
constexpr uint8_t kLegoRunIdle = 0x00, kLegoRunRunning = 0x20;
// Input sensor type of a port with an ultrasonic sensor (I2C with 9 V), and its mode (raw).
constexpr uint8_t kLegoLowSpeed9V = 0x0B, kLegoRawMode = 0x00;

}  // namespace nxtmap::protocol
