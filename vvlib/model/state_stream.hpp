// The bytes of a model's saved state (model/state.hpp): numbers of fixed
// width in little-endian order, doubles by their bits, texts with their
// length. Exact and independent of the machine's byte order; a reader that
// runs past the end or meets a length that cannot be says so (the state is
// truncated or damaged) instead of reading on.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>

namespace vv::model {

//! What a state that cannot be read throws: it names what was being read.
struct state_error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class state_writer {
 public:
  void u8(std::uint8_t v) { out_.push_back(static_cast<char>(v)); }
  void u32(std::uint32_t v) { little_endian(v, 4); }
  void u64(std::uint64_t v) { little_endian(v, 8); }
  void i64(std::int64_t v) { u64(static_cast<std::uint64_t>(v)); }
  void f64(double v) {
    std::uint64_t bits;
    std::memcpy(&bits, &v, 8);
    u64(bits);
  }
  void text(std::string_view s) {
    u64(s.size());
    out_.append(s.data(), s.size());
  }
  //! A length to fill in later (a section's size): its position.
  std::size_t reserve_u64() {
    std::size_t at = out_.size();
    u64(0);
    return at;
  }
  void fill_u64(std::size_t at, std::uint64_t v) {
    for (int i = 0; i < 8; ++i) out_[at + static_cast<std::size_t>(i)] = static_cast<char>((v >> (8 * i)) & 0xffu);
  }
  std::size_t size() const noexcept { return out_.size(); }
  const std::string& bytes() const noexcept { return out_; }
  std::string& bytes() noexcept { return out_; }

 private:
  void little_endian(std::uint64_t v, int n) {
    for (int i = 0; i < n; ++i) out_.push_back(static_cast<char>((v >> (8 * i)) & 0xffu));
  }
  std::string out_;
};

class state_reader {
 public:
  state_reader(const void* data, std::size_t size) noexcept
      : at_(static_cast<const unsigned char*>(data)), end_(at_ + size) {}

  std::uint8_t u8(const char* what) { return static_cast<std::uint8_t>(little_endian(1, what)); }
  std::uint32_t u32(const char* what) { return static_cast<std::uint32_t>(little_endian(4, what)); }
  std::uint64_t u64(const char* what) { return little_endian(8, what); }
  std::int64_t i64(const char* what) { return static_cast<std::int64_t>(u64(what)); }
  double f64(const char* what) {
    std::uint64_t bits = u64(what);
    double v;
    std::memcpy(&v, &bits, 8);
    return v;
  }
  std::string text(const char* what) {
    std::uint64_t n = u64(what);
    need(n, what);
    std::string s(reinterpret_cast<const char*>(at_), static_cast<std::size_t>(n));
    at_ += n;
    return s;
  }
  //! A count of items of at least `item_bytes` each: one larger than the
  //! bytes left is damage, not a reason to allocate.
  std::uint64_t count(const char* what, std::size_t item_bytes = 1) {
    std::uint64_t n = u64(what);
    if (item_bytes && n > left() / item_bytes) throw state_error(std::string("a count that cannot be (") + what + ")");
    return n;
  }
  std::size_t left() const noexcept { return static_cast<std::size_t>(end_ - at_); }
  //! The next n bytes as a reader of their own; this one moves past them.
  state_reader part(std::uint64_t n, const char* what) {
    need(n, what);
    state_reader r(at_, static_cast<std::size_t>(n));
    at_ += n;
    return r;
  }

 private:
  void need(std::uint64_t n, const char* what) const {
    if (n > left()) throw state_error(std::string("the state ends inside ") + what);
  }
  std::uint64_t little_endian(int n, const char* what) {
    need(static_cast<std::uint64_t>(n), what);
    std::uint64_t v = 0;
    for (int i = 0; i < n; ++i) v |= std::uint64_t(at_[i]) << (8 * i);
    at_ += n;
    return v;
  }
  const unsigned char* at_;
  const unsigned char* end_;
};

}  // namespace vv::model
