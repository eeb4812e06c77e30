#pragma once
// Everything haptex prints passes through here (installed on std::cout and std::cerr by run_main): a
// name taken from a file or the command line may hold a terminal's escape sequences, which must not
// reach the terminal. Every character text::acts_on_text names (controls but newline and tab; the
// format characters that reorder or break text, U+202E RIGHT-TO-LEFT OVERRIDE among them) is written
// as \xHH or \uHHHH (DEL as \u007f, a character beyond U+FFFF as a surrogate pair \uHHHH\uHHHH, so
// that JSON output stays JSON); everything else passes unchanged (JSON output holds no control below
// 0x20: nlohmann escapes them itself). A UTF-8 character is held until its last byte has come.
#include <ostream>
#include <streambuf>
#include <string>
#include <string_view>

namespace haptex::apps {

class PrintableBuffer : public std::streambuf {
 public:
  explicit PrintableBuffer(std::streambuf* target) : target_(target) {}
  std::streambuf* target() const { return target_; }
  bool written() const { return written_; }  // whether anything was printed through it

 protected:
  int_type overflow(int_type c) override;
  int sync() override;

 private:
  bool put(std::string_view text);
  bool flush_pending();
  std::streambuf* target_;
  std::string pending_;       // the bytes of a UTF-8 character begun, not yet complete
  std::size_t expected_ = 0;  // its length
  bool written_ = false;
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
  bool written() const { return buffer_.written(); }

 private:
  std::ostream& stream_;
  PrintableBuffer buffer_;
};

}  // namespace haptex::apps
