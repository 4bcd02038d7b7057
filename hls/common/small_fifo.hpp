// A fixed-depth FIFO of registers for hls modules (static size, no allocation), used as the
// output buffer that lets a registered ready keep one transaction per clock.
#pragma once

#include <array>
#include <cstddef>

namespace tmu::hls {

template <class T, size_t Depth>
class SmallFifo {
 public:
  bool empty() const { return count_ == 0; }
  bool full() const { return count_ == Depth; }
  size_t size() const { return count_; }
  const T& front() const { return data_[head_]; }
  void push(const T& v) {
    data_[(head_ + count_) % Depth] = v;
    ++count_;
  }
  void pop() {
    head_ = (head_ + 1) % Depth;
    --count_;
  }
  void clear() { head_ = count_ = 0; }

 private:
  std::array<T, Depth> data_{};
  size_t head_ = 0;
  size_t count_ = 0;
};

}  // namespace tmu::hls
