#pragma once
/// A non-owning view of contiguous elements (C++17 has no std::span).

#include <array>
#include <cstddef>
#include <vector>

#include "simhuman/core/check.h"

namespace simhuman::core {

/// A pointer and a length; the viewed elements must outlive the span. Indexing is checked.
template <typename T>
class Span {
 public:
  Span() = default;
  Span(T* data, int size) : data_(data), size_(size) {}
  template <typename U, typename A>
  Span(std::vector<U, A>& v) : data_(v.data()), size_(static_cast<int>(v.size())) {}  // NOLINT
  template <typename U, typename A>
  Span(const std::vector<U, A>& v)  // NOLINT
      : data_(v.data()), size_(static_cast<int>(v.size())) {}
  template <typename U, size_t N>
  Span(std::array<U, N>& a) : data_(a.data()), size_(static_cast<int>(N)) {}  // NOLINT
  template <typename U, size_t N>
  Span(const std::array<U, N>& a) : data_(a.data()), size_(static_cast<int>(N)) {}  // NOLINT

  T* data() const { return data_; }
  int size() const { return size_; }
  bool empty() const { return size_ == 0; }
  T& operator[](int i) const {
    SH_CHECK(i >= 0 && i < size_, "span index out of range");
    return data_[i];
  }
  T* begin() const { return data_; }
  T* end() const { return data_ + size_; }

 private:
  T* data_ = nullptr;
  int size_ = 0;
};

}  // namespace simhuman::core
