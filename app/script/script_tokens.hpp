#pragma once

// A script line's words and the readers of their values, each throwing a one-line LineError.
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace steerseg::script::detail {

class LineError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

// Splits a line into words at blanks; "double quotes" keep blanks (\" and \\ escape inside),
// an unquoted # starts the comment. Throws on an unterminated quote.
std::vector<std::string> splitWords(std::string_view line);

// The line up to its comment (an unquoted #).
std::string_view withoutComment(std::string_view line);

// The words after the verb, consumed left to right.
class Words {
  public:
    Words(std::vector<std::string> words, std::size_t first)
        : words_(std::move(words)), at_(first) {}

    [[nodiscard]] bool empty() const { return at_ >= words_.size(); }
    std::string text(const char* what);
    // A finite number within [min, max]; `what` names it in the message.
    double number(const char* what, double min, double max);
    long long integer(const char* what, long long min, long long max);
    // The next word if it equals `word` (consumed), else nothing consumed.
    bool accept(std::string_view word);
    // Throws unless every word was read ("unexpected 'x' after ...").
    void finish(const char* usage) const;

  private:
    std::vector<std::string> words_;
    std::size_t at_;
};

// Checks the $NAME / ${NAME} references of a path-like word against scriptVariables().
void checkVariables(std::string_view word);

} // namespace steerseg::script::detail
