#pragma once
#include <cstddef>
#include <cstdint>

#include "common/protocol/Telegram.hpp"

// LEGO direct commands from the PC's side: requests and reply parsing, with LEGO's byte layouts
// (LegoFormat.hpp). The brick's answers are LegoServer's.
namespace nxtmap::protocol {

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
