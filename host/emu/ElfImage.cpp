#include "host/emu/ElfImage.hpp"

#include <elf.h>

#include <algorithm>

#include <cstring>

#include "host/sim/InputFile.hpp"

namespace nxtmap::emu {

namespace {
template <typename T>
bool readAt(const std::vector<uint8_t>& file, uint64_t offset, T& out) {
  if (offset > file.size() || file.size() - offset < sizeof(T)) return false;
  std::memcpy(&out, file.data() + offset, sizeof(T));  // host is little-endian like the ELF (checked)
  return true;
}
}  // namespace

struct ElfLoader {
  static bool isBinName(const std::string& path) {
    return path.size() > 4 && path.compare(path.size() - 4, 4, ".bin") == 0;
  }

  // A raw flash image: its bytes at kFlashBase, the rest erased (0xFF); it starts at the reset vector.
  static ElfLoad raw(const std::string& path, const std::vector<uint8_t>& file) {
    ElfLoad result;
    if (file.empty() || file.size() > kFlashSize) {
      result.error = path + ": a raw flash image must hold 1.." + std::to_string(kFlashSize) + " bytes, not " +
                     std::to_string(file.size());
      return result;
    }
    ElfImage img;
    img.path_ = path;
    img.raw_ = true;
    std::memcpy(img.flash_.data(), file.data(), file.size());
    img.flashUsed_ = static_cast<uint32_t>(file.size());
    img.entry_ = kFlashBase;
    result.image = std::move(img);
    return result;
  }

  static ElfLoad run(const std::string& path) {
    ElfLoad result;
    auto fail = [&](const std::string& why) {
      result.error = path + ": " + why;
      return result;
    };
    std::string readError;
    const std::optional<std::string> bytes = sim::readInputFile(path, kMaxElfBytes, "firmware file", readError);
    if (!bytes) {
      result.error = readError;
      return result;
    }
    const std::vector<uint8_t> file(bytes->begin(), bytes->end());
    if (isBinName(path)) return raw(path, file);
    Elf32_Ehdr eh{};
    if (!readAt(file, 0, eh) || std::memcmp(eh.e_ident, ELFMAG, SELFMAG) != 0) return fail("not an ELF file");
    if (eh.e_ident[EI_CLASS] != ELFCLASS32 || eh.e_ident[EI_DATA] != ELFDATA2LSB || eh.e_machine != EM_ARM)
      return fail("not a 32-bit little-endian ARM ELF");
    if (eh.e_phentsize != sizeof(Elf32_Phdr) || eh.e_phnum == 0) return fail("no program headers");

    ElfImage img;
    img.path_ = path;
    img.entry_ = eh.e_entry;
    for (unsigned i = 0; i < eh.e_phnum; ++i) {
      Elf32_Phdr ph{};
      if (!readAt(file, uint64_t{eh.e_phoff} + uint64_t{i} * sizeof ph, ph)) return fail("truncated program header");
      if (ph.p_type != PT_LOAD || ph.p_filesz == 0) continue;
      if (ph.p_offset > file.size() || file.size() - ph.p_offset < ph.p_filesz) return fail("truncated segment");
      const uint64_t lo = ph.p_paddr;
      const uint64_t hi = lo + ph.p_filesz;
      const uint8_t* src = file.data() + ph.p_offset;
      if (lo >= kFlashBase && hi <= uint64_t{kFlashBase} + kFlashSize) {
        std::memcpy(img.flash_.data() + (lo - kFlashBase), src, ph.p_filesz);
        img.flashUsed_ = std::max<uint32_t>(img.flashUsed_, static_cast<uint32_t>(hi - kFlashBase));
      } else if (lo >= kRamBase && hi <= uint64_t{kRamBase} + kRamSize) {
        std::memcpy(img.ram_.data() + (lo - kRamBase), src, ph.p_filesz);
        img.ramSegments_.emplace_back(static_cast<uint32_t>(lo - kRamBase), ph.p_filesz);
      } else {
        char buf[96];
        std::snprintf(buf, sizeof buf, "segment at 0x%08x..0x%08x is outside flash and RAM", static_cast<unsigned>(lo),
                      static_cast<unsigned>(hi));
        return fail(buf);
      }
    }
    // Symbols.
    if (eh.e_shentsize == sizeof(Elf32_Shdr)) {
      for (unsigned i = 0; i < eh.e_shnum; ++i) {
        Elf32_Shdr sh{};
        if (!readAt(file, uint64_t{eh.e_shoff} + uint64_t{i} * sizeof sh, sh)) break;
        if (sh.sh_type != SHT_SYMTAB || sh.sh_entsize != sizeof(Elf32_Sym)) continue;
        Elf32_Shdr strh{};
        if (!readAt(file, uint64_t{eh.e_shoff} + uint64_t{sh.sh_link} * sizeof strh, strh)) break;
        for (uint32_t off = 0; off + sizeof(Elf32_Sym) <= sh.sh_size; off += sizeof(Elf32_Sym)) {
          Elf32_Sym sym{};
          if (!readAt(file, uint64_t{sh.sh_offset} + off, sym)) break;
          if (sym.st_name == 0 || sym.st_name >= strh.sh_size) continue;
          const uint64_t at = uint64_t{strh.sh_offset} + sym.st_name;
          if (at >= file.size()) continue;
          const char* s = reinterpret_cast<const char*>(file.data() + at);
          const size_t maxLen = file.size() - at;
          const size_t len = strnlen(s, maxLen);
          if (len == maxLen) continue;
          img.symbols_.emplace(std::string(s, len), sym.st_value);
          if (ELF32_ST_TYPE(sym.st_info) == STT_FUNC && sym.st_size > 0)
            img.functions_.push_back(FunctionSymbol{sym.st_value & ~1u, sym.st_size, std::string(s, len)});
        }
      }
    }
    std::sort(img.functions_.begin(), img.functions_.end(),
              [](const FunctionSymbol& a, const FunctionSymbol& b) { return a.address < b.address; });
    if (img.flashUsed_ == 0 && img.entry_ < kRamBase) return fail("no code in flash or RAM");
    result.image = std::move(img);
    return result;
  }
};

ElfLoad ElfImage::load(const std::string& path) { return ElfLoader::run(path); }

std::optional<uint32_t> ElfImage::symbol(const std::string& name) const {
  const auto it = symbols_.find(name);
  if (it == symbols_.end()) return std::nullopt;
  return it->second;
}

const FunctionSymbol* ElfImage::functionAt(uint32_t address) const {
  auto it = std::upper_bound(functions_.begin(), functions_.end(), address,
                             [](uint32_t a, const FunctionSymbol& f) { return a < f.address; });
  if (it == functions_.begin()) return nullptr;
  --it;
  return address - it->address < it->size ? &*it : nullptr;
}

std::optional<uint32_t> ElfImage::firstSymbol(std::initializer_list<const char*> names) const {
  for (const char* n : names)
    if (auto v = symbol(n)) return v;
  return std::nullopt;
}

void ElfImage::keepPagesFrom(const std::vector<uint8_t>& saved) {
  constexpr uint32_t kPage = 256;
  const uint32_t from = (flashUsed_ + kPage - 1) / kPage * kPage;
  if (saved.size() != kFlashSize || from >= kFlashSize) return;
  std::copy(saved.begin() + from, saved.end(), flash_.begin() + from);
}

}  // namespace nxtmap::emu
