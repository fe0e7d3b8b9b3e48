// Per-effect storage for what the syntax-tree nodes hold by the handful: the lists of
// annotations, states, passes, members, parameters and array sizes (ast::List) and the
// texts of names (std::string_view into the arena). Everything is bump-allocated in blocks
// and freed with the arena, so a 10 MB effect costs a few hundred allocations instead of
// one per list or long name, nothing is destroyed element by element, and a declaration's
// lists lie next to each other in parse order for the checker.
#pragma once
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace fx::ast {

// A name or other text in a node: a std::string_view into the effect's Arena (a tree built
// by hand may point it at anything that outlives the tree). It converts to std::string
// where one is needed and joins with `+` as a std::string would, so code written against
// std::string members reads it unchanged.
class Text : public std::string_view {
 public:
  using std::string_view::string_view;
  constexpr Text(std::string_view s) : std::string_view(s) {}
  operator std::string() const { return std::string(data(), size()); }
  std::string str() const { return std::string(data(), size()); }

  friend std::string operator+(const std::string& a, const Text& b) { return join(a, b); }
  friend std::string operator+(std::string&& a, const Text& b) { return std::move(a.append(b)); }
  friend std::string operator+(const Text& a, const std::string& b) { return join(a, b); }
  friend std::string operator+(const char* a, const Text& b) { return join(a, b); }
  friend std::string operator+(const Text& a, const char* b) { return join(a, b); }
  friend std::string operator+(char a, const Text& b) { return join({&a, 1}, b); }
  friend std::string operator+(const Text& a, char b) { return join(a, {&b, 1}); }
  friend std::string operator+(const Text& a, const Text& b) { return join(a, b); }

 private:
  static std::string join(std::string_view a, std::string_view b) {
    std::string s;
    s.reserve(a.size() + b.size());
    return std::move(s.append(a).append(b));
  }
};

class Arena {
 public:
  Arena() = default;
  Arena(Arena&& other) noexcept
      : blocks_(std::exchange(other.blocks_, {})),
        next_(std::exchange(other.next_, nullptr)),
        left_(std::exchange(other.left_, 0)),
        last_size_(std::exchange(other.last_size_, 0)) {}
  Arena& operator=(Arena&& other) noexcept {
    if (this != &other) {
      blocks_ = std::exchange(other.blocks_, {});
      next_ = std::exchange(other.next_, nullptr);
      left_ = std::exchange(other.left_, 0);
      last_size_ = std::exchange(other.last_size_, 0);
    }
    return *this;
  }

  // `bytes` of uninitialized storage aligned to `align` (a power of two), valid until the
  // arena is destroyed.
  void* allocate(size_t bytes, size_t align) {
    size_t pad = (0 - reinterpret_cast<uintptr_t>(next_)) & (align - 1);
    if (pad + bytes > left_) return allocate_slow(bytes, align);
    void* p = next_ + pad;
    next_ += pad + bytes;
    left_ -= pad + bytes;
    return p;
  }
  // A stored copy of `s` (empty views stay empty and take no storage).
  Text text(std::string_view s) {
    if (s.empty()) return {};
    char* p = static_cast<char*>(allocate(s.size(), 1));
    std::memcpy(p, s.data(), s.size());
    return {p, s.size()};
  }

 private:
  // Blocks start small, so a small effect does not pay for a big block, and double up to
  // kMaxBlock; a request larger than that gets a block of its own.
  static constexpr size_t kFirstBlock = 4096, kMaxBlock = size_t(8) << 20;
  static constexpr size_t kHugeBlock = size_t(4) << 20;  // advised for huge pages from here
  void* allocate_slow(size_t bytes, size_t align);

  std::vector<std::unique_ptr<std::byte[]>> blocks_;
  std::byte* next_ = nullptr;
  size_t left_ = 0;       // bytes free after next_ in the current block
  size_t last_size_ = 0;  // size of the last regular block
};

// A list whose elements live in an Arena: the read side of a std::vector (iteration,
// size, indexing) and growth through the arena that stores it. Elements must be trivially
// copyable and destructible (every node type is); growing copies them to a new, larger
// range of the arena. A copy of a List shares its elements with the original, as a span
// does, so a list is filled through one copy only.
template <class T>
class List {
 public:
  using value_type = T;
  using iterator = T*;
  using const_iterator = const T*;

  List() = default;

  T* begin() { return data_; }
  T* end() { return data_ + size_; }
  const T* begin() const { return data_; }
  const T* end() const { return data_ + size_; }
  T* data() { return data_; }
  const T* data() const { return data_; }
  size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  T& operator[](size_t i) { return data_[i]; }
  const T& operator[](size_t i) const { return data_[i]; }
  // Bounds-checked, as std::vector::at: throws std::out_of_range.
  T& at(size_t i) { return i < size_ ? data_[i] : out_of_range(); }
  const T& at(size_t i) const { return i < size_ ? data_[i] : out_of_range(); }
  T& front() { return data_[0]; }
  const T& front() const { return data_[0]; }
  T& back() { return data_[size_ - 1]; }
  const T& back() const { return data_[size_ - 1]; }
  operator std::span<const T>() const { return {data_, size_}; }

  // Room for `n` elements in all without growing again.
  void reserve(Arena& arena, size_t n) {
    if (n > capacity_) grow(arena, n);
  }
  // A new value-initialized element at the end.
  T& emplace_back(Arena& arena) {
    if (size_ == capacity_) grow(arena, std::max<size_t>(4, 2 * size_t{capacity_}));
    return *std::construct_at(data_ + size_++);
  }
  void push_back(Arena& arena, const T& value) { emplace_back(arena) = value; }
  void pop_back() { --size_; }
  void clear() { size_ = 0; }

 private:
  void grow(Arena& arena, size_t capacity) {
    static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>);
    T* data = static_cast<T*>(arena.allocate(capacity * sizeof(T), alignof(T)));
    if (size_ != 0) std::memcpy(static_cast<void*>(data), data_, size_ * sizeof(T));
    data_ = data;
    capacity_ = static_cast<uint32_t>(capacity);
  }

  [[noreturn]] static T& out_of_range() { throw std::out_of_range("ast::List::at"); }

  T* data_ = nullptr;
  uint32_t size_ = 0, capacity_ = 0;
};

}  // namespace fx::ast
