#pragma once
#include <cstddef>
#include <cstdint>

#include "common/protocol/Mailboxes.hpp"
#include "common/protocol/Telegram.hpp"

// LEGO direct commands: the brick's answers, and the PC's requests and reply parsing, with
// LEGO's byte layouts (see WireFormat.hpp).
namespace nxtmap::protocol {

// Carries out a served direct command (a telegram FrameDecoder accepted) and builds LEGO's
// reply. Returns false when no reply is due (type 0x80) or the telegram is not a served
// direct command. `batteryMillivolts` answers GET_BATTERY_LEVEL; KEEP_ALIVE answers
// `sleepLimitMs`. MESSAGE_WRITE/READ use `boxes` (READ's remote inbox 10..19 reads box - 10,
// LEGO's convention for the brick's outboxes).
bool answerDirectCommand(const Telegram& command, Mailboxes& boxes, uint16_t batteryMillivolts, uint32_t sleepLimitMs,
                         Frame& reply);

// PC side: requests.
bool encodeGetBatteryLevel(Frame& out);
bool encodeKeepAlive(Frame& out);
bool encodeMessageWrite(uint8_t box, const char* text, Frame& out);  // text of up to 58 characters
bool encodeMessageRead(uint8_t remoteBox, uint8_t localBox, bool remove, Frame& out);

// PC side: replies (a reply telegram as FrameDecoder delivered it).
bool decodeBatteryReply(const Telegram& t, uint8_t& status, uint16_t& millivolts);
bool decodeKeepAliveReply(const Telegram& t, uint8_t& status, uint32_t& sleepLimitMs);
bool decodeMessageWriteReply(const Telegram& t, uint8_t& status);
// `text` receives the message without its NUL (at most 58 characters + NUL).
bool decodeMessageReadReply(const Telegram& t, uint8_t& status, uint8_t& box, char (&text)[kLegoMaxMessage + 1]);

}  // namespace nxtmap::protocol
