#include "host/emu/MachineHooks.hpp"

#include "host/emu/AlignedAccess.hpp"
#include "host/emu/DirectStores.hpp"
#include "host/log/Log.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>

namespace nxtmap::emu {

std::string hexWord(uint32_t v) {
  char b[16];
  std::snprintf(b, sizeof b, "0x%08x", static_cast<unsigned>(v));
  return b;
}

// Every block passes here (10 % of the host time): the common case (no flash work, no timed return, no stop,
// the code's state known) in a few instructions; anything else in blockInFull, which handles every case.
void Machine::Hooks::block(uc_engine* uc, uint64_t address, uint32_t size, void* user) {
  auto* m = static_cast<Machine*>(user);
  const auto a = static_cast<uint32_t>(address);
  const int slot = m->modeSlot(a);
  const uint8_t mode = slot < 0 ? 0 : m->modes_[static_cast<size_t>(slot)];
  if (mode == 0 || a == m->timedReturn_ || m->clock_.now >= m->clock_.stopAt || !m->flashRestore_.empty() ||
      m->efc_.busy() || m->trace_ || m->profiling()) {
    blockInFull(uc, address, size, user);
    return;
  }
  const uint64_t n = mode == 2 ? size / 2 : size / 4;
  m->blockStart_ = m->clock_.now;
  m->clock_.now += n;
  m->executed_ += n;
  m->lastBlock_ = a;
  m->lastBlockBytes_ = size;
  m->blockWrites_ = 0;
}

void Machine::Hooks::blockInFull(uc_engine* uc, uint64_t address, uint32_t size, void* user) {
  auto* m = static_cast<Machine*>(user);
  if (!m->flashRestore_.empty()) m->restoreFlash();
  if (m->efc_.busy() && m->inFlash(static_cast<uint32_t>(address))) {
    m->setFault(FaultKind::BadMemory, static_cast<uint32_t>(address),
                "instruction fetch from flash while the flash controller programs it (FRDY 0)");
    uc_emu_stop(uc);
    return;
  }
  if (m->timedReturn_ != 0 && static_cast<uint32_t>(address) == m->timedReturn_) {
    m->maxTimed_ = std::max(m->maxTimed_, m->clock_.now - m->timedStart_);
    ++m->timedCalls_;
    if (m->profiling()) m->profile_->endCall(m->clock_.now - m->timedStart_);
    m->timedReturn_ = 0;
  }
  if (m->clock_.now >= m->clock_.stopAt) {
    uc_emu_stop(uc);  // before the block: PC == address, the block does not run
    m->stoppedAt_ = static_cast<uint32_t>(address);
    return;
  }
  // ARM or Thumb: learnt once per code address (reading CPSR in every block costs ~5 %).
  const int slot = m->modeSlot(static_cast<uint32_t>(address));
  uint32_t cpsr = 0;
  if (slot < 0 || m->modes_[static_cast<size_t>(slot)] == 0 || m->trace_) {
    if (m->directRam_ && static_cast<uint32_t>(address) - kRamBase < kRamSize) {
      m->directRam_ = false;  // code runs from RAM: stores there must look for translated code again
      setDirectRamStores(0, 0);
      flushTlb(m->cpu_);
    }
    uc_reg_read(uc, UC_ARM_REG_CPSR, &cpsr);
    if (slot >= 0) m->modes_[static_cast<size_t>(slot)] = (cpsr & kCpsrT) ? 2 : 1;
  } else if (m->modes_[static_cast<size_t>(slot)] == 2) {
    cpsr = kCpsrT;
  }
  if (m->trace_)
    log::debug("emu", "block %08x size %u cpsr %08x t=%llu", static_cast<unsigned>(address), size, cpsr,
               static_cast<unsigned long long>(m->clock_.now));
  const uint64_t n = (cpsr & kCpsrT) ? size / 2 : size / 4;
  if (m->profiling()) m->profile_->count(static_cast<uint32_t>(address), n);
  m->blockStart_ = m->clock_.now;
  m->clock_.now += n;
  m->executed_ += n;
  m->lastBlock_ = static_cast<uint32_t>(address);
  m->lastBlockBytes_ = size;
  m->blockWrites_ = 0;
}

void Machine::Hooks::timedEntry(uc_engine* uc, uint64_t, uint32_t, void* user) {
  auto* m = static_cast<Machine*>(user);
  if (m->timedReturn_ != 0) return;  // nested or recursive: time the outermost call only
  uint32_t lr = 0;
  uc_reg_read(uc, UC_ARM_REG_LR, &lr);
  m->timedReturn_ = lr & ~1u;
  m->timedStart_ = m->blockStart_;  // the entry starts its block (it is reached by a branch)
  if (m->profile_) {
    m->profile_->beginCall();
    m->profile_->count(m->lastBlock_, m->clock_.now - m->blockStart_);
  }
}

void Machine::Hooks::memAccess(uc_engine* uc, uc_mem_type type, uint64_t address, int size, int64_t, void* user) {
  auto* m = static_cast<Machine*>(user);
  const auto a = static_cast<uint32_t>(address);
  if (type == UC_MEM_WRITE) ++m->blockWrites_;
  if (m->options_.checkAlignment && (a & static_cast<uint32_t>(size - 1)) != 0) {
    m->setFault(FaultKind::Unaligned, a,
                std::string(type == UC_MEM_WRITE ? "write" : "read") + " of " + std::to_string(size) + " bytes");
    uc_emu_stop(uc);
    return;
  }
  if (type == UC_MEM_WRITE && m->guard_.contains(a)) {
    m->stackOverflow(a);
    uc_emu_stop(uc);
  }
}

bool Machine::Hooks::badMemory(uc_engine* uc, uc_mem_type type, uint64_t address, int size, int64_t value, void* user) {
  auto* m = static_cast<Machine*>(user);
  const auto a = static_cast<uint32_t>(address);
  if (type == UC_MEM_WRITE_PROT && m->inFlash(a)) {  // the EFC latch (the store itself is undone)
    const uint32_t off = (a >= kFlashBase ? a - kFlashBase : a) & ~3u;
    FlashWord w{off, {}};
    std::memcpy(w.bytes, m->flash_ + off, 4);
    m->flashRestore_.push_back(w);
    m->efc_.latchWrite(a >= kFlashBase ? a - kFlashBase : a, static_cast<uint32_t>(value), size);
    return true;
  }
  if (type == UC_MEM_WRITE_PROT && m->guard_.contains(a)) {  // a read-only page of the guard (StackGuard)
    m->stackOverflow(a);
    return false;  // the store does not run
  }
  uint32_t sp = 0;
  uc_reg_read(uc, UC_ARM_REG_SP, &sp);
  const char* what = "access";
  switch (type) {
    case UC_MEM_READ_UNMAPPED: what = "read of unmapped memory"; break;
    case UC_MEM_WRITE_UNMAPPED: what = "write to unmapped memory"; break;
    case UC_MEM_FETCH_UNMAPPED: what = "instruction fetch from unmapped memory"; break;
    case UC_MEM_WRITE_PROT: what = "write to read-only memory (flash)"; break;
    case UC_MEM_FETCH_PROT: what = "instruction fetch from non-executable memory"; break;
    default: break;
  }
  const bool stackish = (type == UC_MEM_WRITE_UNMAPPED || type == UC_MEM_WRITE_PROT) && a + 64 >= sp && a <= sp + 64 &&
                        a < kRamBase + kRamSize;
  if (stackish)
    m->setFault(FaultKind::StackOverflow, a, std::string(what) + " at the stack pointer " + hexWord(sp));
  else
    m->setFault(FaultKind::BadMemory, a, std::string(what) + " (" + std::to_string(size) + " bytes)");
  return false;
}

void Machine::Hooks::interrupt(uc_engine* uc, uint32_t intno, void* user) {
  auto* m = static_cast<Machine*>(user);
  constexpr uint32_t kDataAbort = 4;  // QEMU's EXCP_DATA_ABORT
  if (intno == kDataAbort) {
    if (const std::optional<UnalignedAccess> a = takeUnalignedAccess()) {  // the access did not run
      m->setFault(FaultKind::Unaligned, a->address, m->unalignedWhat(a->store));
      uc_emu_stop(uc);
      return;
    }
  }
  static const char* names[] = {
      "reset",      "undefined instruction", "SWI",        "prefetch abort", "data abort", "IRQ", "FIQ",
      "breakpoint", "exception return",      "kernel trap"};
  const std::string name = intno < 10 ? names[intno] : "exception " + std::to_string(intno);
  m->setFault(FaultKind::Exception, 0, name + " (no handler is emulated)");
  uc_emu_stop(uc);
}

bool Machine::Hooks::invalidInsn(uc_engine*, void* user) {
  auto* m = static_cast<Machine*>(user);
  m->setFault(FaultKind::Exception, 0, "undefined instruction (or one the ARMv4T ARM7TDMI lacks)");
  return false;
}

Machine::Slot* Machine::Hooks::slotFor(Machine* m, uint64_t offset) {
  const uint8_t idx = m->page_[offset >> 4];
  return idx ? &m->slots_[idx - 1u] : nullptr;
}

uint64_t Machine::Hooks::mmioRead(uc_engine* uc, uint64_t offset, unsigned size, void* user) {
  auto* m = static_cast<Machine*>(user);
  const auto a = static_cast<uint32_t>(kMmioBase + offset);
  Slot* s = slotFor(m, offset);
  uint32_t v = 0;
  if (!s || !s->device->read((a - s->base) & ~3u, v)) {
    m->setFault(FaultKind::UnmodelledIo, a,
                std::string("read of ") + (s ? s->device->name() : "an unmapped peripheral") + " register +" +
                    hexWord(s ? a - s->base : offset));
    uc_emu_stop(uc);
    return 0;
  }
  if (size < 4) v >>= 8 * (a & 3);
  return v;
}

void Machine::Hooks::mmioWrite(uc_engine* uc, uint64_t offset, unsigned size, uint64_t value, void* user) {
  auto* m = static_cast<Machine*>(user);
  const auto a = static_cast<uint32_t>(kMmioBase + offset);
  Slot* s = slotFor(m, offset);
  auto v = static_cast<uint32_t>(value);
  if (size < 4) v <<= 8 * (a & 3);
  if (!s || !s->device->write((a - s->base) & ~3u, v)) {
    m->setFault(FaultKind::UnmodelledIo, a,
                std::string("write of ") + hexWord(v) + " to " + (s ? s->device->name() : "an unmapped peripheral") +
                    " register +" + hexWord(s ? a - s->base : offset));
    uc_emu_stop(uc);
    return;
  }
  if (s->device->writeReplans((a - s->base) & ~3u)) {
    m->clock_.poke();  // re-plan at the next block
    m->irqAfterStore(a, size, static_cast<uint32_t>(value));
  }
}

}  // namespace nxtmap::emu
