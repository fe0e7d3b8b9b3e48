// The rare, out-of-line part of fx::Token: spellings too long for its 16-bit length.
#include "fx/token.h"

#include "fx/source_manager.h"

namespace fx {

void Token::set_long_text(std::string_view text, SourceManager& sm) {
  text_.long_view = sm.keep_long_spelling(text);
  text_size_ = kLongText;
}

}  // namespace fx
