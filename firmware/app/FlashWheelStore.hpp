#pragma once
#include <cstdint>

#include "common/motion/WheelRecord.hpp"
#include "firmware/app/WheelStore.hpp"
#include "firmware/board/FlashPage.hpp"

namespace nxtmap::fw {

// FlashWheelStore: the learnt wheels as a WheelRecord in the last page of the brick's flash
// (WheelRecord::kFlashPage), written through FlashPage. A page that holds no whole record loads as nothing.
// A save writes the page only when the record differs from the one kept: at most once per run (a page lasts
// 10,000 writes); it takes about 6 ms with interrupts held off, while the robot rests.
template <class Bus>
class FlashWheelStore final : public WheelStore {
 public:
  explicit FlashWheelStore(FlashPage<Bus> page) : page_(page) {}

  bool load(WheelCalibration& w) const override {
    uint32_t words[WheelRecord::kWords];
    for (int i = 0; i < WheelRecord::kWords; ++i)
      words[i] = page_.read(WheelRecord::kFlashPage, static_cast<uint32_t>(i));
    return WheelRecord::decode(words, w);
  }

  bool save(const WheelCalibration& w) override {
    WheelCalibration kept;
    if (load(kept) && WheelRecord::same(kept, w)) return true;
    uint32_t words[WheelRecord::kWords];
    WheelRecord::encode(w, words);
    return page_.write(WheelRecord::kFlashPage, words, WheelRecord::kWords);
  }

 private:
  FlashPage<Bus> page_;
};

}  // namespace nxtmap::fw
