#include "compile/object_symbols.hpp"

#include <elf.h>

#include <cstring>
#include <optional>

#include "app/files.hpp"

namespace vvi {

namespace {

// A view of a relocatable ELF64 file of this machine's byte order, with
// every offset checked against its size.
class elf_file {
 public:
  explicit elf_file(const std::string& bytes) : b_(bytes) {}

  bool header_ok() {
    if (b_.size() < sizeof(Elf64_Ehdr) || std::memcmp(b_.data(), ELFMAG, SELFMAG) != 0) return false;
    std::memcpy(&eh_, b_.data(), sizeof eh_);
    const bool little = __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__;
    return eh_.e_ident[EI_CLASS] == ELFCLASS64 && eh_.e_ident[EI_DATA] == (little ? ELFDATA2LSB : ELFDATA2MSB) &&
           eh_.e_type == ET_REL && eh_.e_shentsize == sizeof(Elf64_Shdr) && fits(eh_.e_shoff, eh_.e_shnum, sizeof(Elf64_Shdr));
  }
  std::size_t sections() const { return eh_.e_shnum; }
  Elf64_Shdr section(std::size_t i) const {
    Elf64_Shdr s;
    std::memcpy(&s, b_.data() + eh_.e_shoff + i * sizeof s, sizeof s);
    return s;
  }
  bool fits(std::uint64_t offset, std::uint64_t count, std::uint64_t size) const {
    return offset <= b_.size() && (size == 0 || count <= (b_.size() - offset) / size);
  }
  //! The NUL-terminated string at `at` in the string table `table`, or "".
  std::string string_in(const Elf64_Shdr& table, std::uint64_t at) const {
    if (at >= table.sh_size || !fits(table.sh_offset, table.sh_size, 1)) return "";
    const char* start = b_.data() + table.sh_offset + at;
    std::size_t room = table.sh_size - at;
    return std::string(start, strnlen(start, room));
  }
  std::string section_name(std::size_t i) const {
    if (eh_.e_shstrndx >= eh_.e_shnum) return "";
    return string_in(section(eh_.e_shstrndx), section(i).sh_name);
  }
  Elf64_Sym symbol(const Elf64_Shdr& table, std::size_t i) const {
    Elf64_Sym s;
    std::memcpy(&s, b_.data() + table.sh_offset + i * sizeof s, sizeof s);
    return s;
  }

 private:
  const std::string& b_;
  Elf64_Ehdr eh_{};
};

// The name a C++ symbol declares, past the "_Z<length>" of its mangling
// (a function at namespace scope): "_Z17vv_decl_write_vvm..." -> "vv_decl_write_vvm...".
std::string_view declared_name(std::string_view symbol) {
  if (symbol.substr(0, 2) != "_Z") return symbol;
  std::size_t i = 2;
  while (i < symbol.size() && symbol[i] >= '0' && symbol[i] <= '9') ++i;
  return i > 2 ? symbol.substr(i) : symbol;
}

// <iostream>'s per-file object (std::ios_base::Init): every copy does the
// same, setting up the standard streams once.
bool is_stream_initialiser(const std::string& name) { return name == "_ZStL8__ioinit"; }

std::string local_state_in(const elf_file& f, const Elf64_Sym& s, const std::string& name) {
  int type = ELF64_ST_TYPE(s.st_info);
  if ((type != STT_OBJECT && type != STT_TLS) || s.st_shndx >= f.sections() || is_stream_initialiser(name)) return "";
  Elf64_Shdr section = f.section(s.st_shndx);
  // Relocated constants (tables of pointers) are written once, at load.
  if (!(section.sh_flags & SHF_WRITE) || f.section_name(s.st_shndx).rfind(".data.rel.ro", 0) == 0) return "";
  return "writable data of its own (" + name + ")";
}

}  // namespace

std::string definitions_beyond(const std::string& path, const std::string& allowed_prefix) {
  std::optional<std::string> bytes = read_file(path);
  if (!bytes) return "cannot read " + path;
  elf_file f(*bytes);
  if (!f.header_ok()) return path + " is not an object file of this machine";
  for (std::size_t t = 0; t < f.sections(); ++t) {
    Elf64_Shdr table = f.section(t);
    if (table.sh_type != SHT_SYMTAB) continue;
    if (table.sh_entsize != sizeof(Elf64_Sym) || table.sh_link >= f.sections() ||
        !f.fits(table.sh_offset, table.sh_size / sizeof(Elf64_Sym), sizeof(Elf64_Sym)))
      return path + " has a damaged symbol table";
    Elf64_Shdr names = f.section(table.sh_link);
    for (std::size_t i = 1; i < table.sh_size / sizeof(Elf64_Sym); ++i) {
      Elf64_Sym s = f.symbol(table, i);
      int bind = ELF64_ST_BIND(s.st_info), type = ELF64_ST_TYPE(s.st_info);
      if (s.st_shndx == SHN_UNDEF || type == STT_SECTION || type == STT_FILE) continue;
      std::string name = f.string_in(names, s.st_name);
      if (s.st_shndx == SHN_COMMON) return "defines the common symbol " + name;
      if (bind == STB_WEAK || bind == STB_GNU_UNIQUE) continue;  // merged with the program's copy
      if (bind == STB_LOCAL) {
        std::string state = local_state_in(f, s, name);
        if (!state.empty()) return state;
        continue;
      }
      if (type == STT_FUNC && declared_name(name).substr(0, allowed_prefix.size()) == allowed_prefix) continue;
      return "defines the global symbol " + name;
    }
  }
  return "";
}

}  // namespace vvi
