#pragma once
// A log for one of several calibrations running together: whole lines, each prefixed with the
// calibration's tag, written to the shared log under one lock as soon as they end, so a user
// watching stderr sees every calibration's progress live (lines of different calibrations
// interleave; a line is never split).
//
//   std::mutex lock;
//   TaggedLog bp("BP", ctx.log, &lock);
//   std::ostream log(&bp);   // log << "candidate 1/6 ...\n" appears as "[BP] candidate 1/6 ..."
#include <mutex>
#include <ostream>
#include <streambuf>
#include <string>

namespace demcal::workflow {

class TaggedLog : public std::streambuf {
 public:
  TaggedLog(std::string tag, std::ostream* out, std::mutex* lock)
      : tag_("[" + std::move(tag) + "] "), out_(out), lock_(lock) {}
  ~TaggedLog() override {
    if (!line_.empty()) Flush();
  }

 protected:
  int_type overflow(int_type c) override {
    if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
    line_.push_back(traits_type::to_char_type(c));
    if (line_.back() == '\n') Flush();
    return c;
  }
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    for (std::streamsize i = 0; i < n; ++i) overflow(traits_type::to_int_type(s[i]));
    return n;
  }

 private:
  void Flush() {
    if (line_.back() != '\n') line_.push_back('\n');
    if (out_) {
      std::lock_guard<std::mutex> hold(*lock_);
      *out_ << tag_ << line_ << std::flush;
    }
    line_.clear();
  }

  std::string tag_;
  std::ostream* out_;
  std::mutex* lock_;
  std::string line_;
};

}  // namespace demcal::workflow
