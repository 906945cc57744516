// A per-pixel word stream of the co-simulation, modelled in C++ and attached by the harness to a
// block's valid/ready input port (e.g. the texture unit's view and shade ports: the words the
// shader hands the unit per pixel, in pixel order), so that the block itself is the Verilator top:
//   StreamSource     the words (preloaded, shared by every run) and a read pointer: valid while
//                    words remain, data = the current word; on each rising clock edge the pointer
//                    advances when valid and ready were both high before the edge (it is held at 0
//                    while rst_ni is low). Nothing else is registered: valid and data follow the
//                    pointer, so they change only after an edge.
//   attach_stream()  puts one stream on a Verilated block's valid / ready / data ports (Env hooks of
//                    the Harness: sample ready before the edge, drive valid and data after it).
// No clock is spent loading the words.
#pragma once

#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

#include "harness.hpp"

namespace tu::cosim {

template <class Word>
class StreamSource {
 public:
  using Words = std::vector<Word>;
  explicit StreamSource(std::shared_ptr<const Words> words) : words_(std::move(words)) {}

  bool valid() const { return rd_ < words_->size(); }
  // The current word; past the last, a zero word (the data a port shows while valid is low).
  const Word& word() const { return valid() ? (*words_)[rd_] : zero_; }
  // Rising clock edge, with rst_ni and the block's ready as they are before the edge.
  void clock(bool rst_n, bool ready) {
    if (!rst_n) rd_ = 0;
    else if (valid() && ready) ++rd_;
  }
  size_t taken() const { return rd_; }

 private:
  std::shared_ptr<const Words> words_;
  size_t rd_ = 0;
  Word zero_{};
};

// Attaches `src` to the block's port: valid(d) returns the Verilated valid input, ready(d) the
// ready output, put(d, word) drives the data inputs (by field name). A fresh stream per run: call
// inside the harness's Env factory.
template <class V, class Word, class Valid, class Ready, class Put>
void attach_stream(Env<V>& env, std::shared_ptr<StreamSource<Word>> src, Valid valid, Ready ready, Put put) {
  env.edge.push_back([=](V& d) { src->clock(d.rst_ni != 0, ready(d) != 0); });
  env.update.push_back([=](V& d) {
    valid(d) = src->valid() ? 1 : 0;
    put(d, src->word());
  });
}

}  // namespace tu::cosim
