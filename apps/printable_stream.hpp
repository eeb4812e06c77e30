#pragma once
// Everything haptex prints passes through here (installed on std::cout and std::cerr by run_main): a
// name taken from a file or the command line may hold a terminal's escape sequences, which must not
// reach the terminal. Control characters (C0 but newline and tab; DEL; C1, which
// UTF-8 writes as 0xC2 0x80..0x9F) are written as \xHH or \u00HH; everything else passes unchanged
// (JSON output holds none: nlohmann escapes them itself).
#include <ostream>
#include <streambuf>

namespace haptex::apps {

class PrintableBuffer : public std::streambuf {
 public:
  explicit PrintableBuffer(std::streambuf* target) : target_(target) {}
  std::streambuf* target() const { return target_; }

 protected:
  int_type overflow(int_type c) override;
  int sync() override;

 private:
  bool put(const char* text);
  std::streambuf* target_;
  bool lead_c2_ = false;  // the last byte was 0xC2: a C1 control may follow
};

// Installs PrintableBuffer on a stream for as long as it lives.
class PrintableStream {
 public:
  explicit PrintableStream(std::ostream& stream) : stream_(stream), buffer_(stream.rdbuf()) { stream_.rdbuf(&buffer_); }
  ~PrintableStream() {
    stream_.flush();
    stream_.rdbuf(buffer_.target());
  }
  PrintableStream(const PrintableStream&) = delete;
  PrintableStream& operator=(const PrintableStream&) = delete;

 private:
  std::ostream& stream_;
  PrintableBuffer buffer_;
};

}  // namespace haptex::apps
