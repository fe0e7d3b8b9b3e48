// docs/packaging.md states what cmake/fxkit.pc.in links: the fxkit libraries, in link
// order. A library added to the .pc file and not to the page sends pkg-config users'
// hand-written link lines to an undefined-symbol error.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace fx::docs {
namespace {

std::string read(const std::string& relative) {
  std::ifstream in(std::string(FXKIT_SOURCE_DIR) + "/" + relative);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Every `-lfxkit_NAME` in `text`, in order.
std::vector<std::string> fxkit_libraries(const std::string& text) {
  std::vector<std::string> out;
  const std::regex library("-l(fxkit_[a-z_]+)");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), library); it != std::sregex_iterator(); ++it)
    out.push_back((*it)[1]);
  return out;
}

TEST(PackagingDoc, ListsTheLibrariesOfFxkitPcInLinkOrder) {
  const std::string pc = read("cmake/fxkit.pc.in");
  const std::string doc = read("docs/packaging.md");
  ASSERT_FALSE(pc.empty() || doc.empty());
  const size_t from = doc.find("`fxkit.pc` lists");
  ASSERT_NE(from, std::string::npos) << "docs/packaging.md no longer says what fxkit.pc lists";
  const std::string sentence = doc.substr(from, doc.find("in link order", from) - from);
  EXPECT_EQ(fxkit_libraries(sentence), fxkit_libraries(pc)) << sentence;
}

}  // namespace
}  // namespace fx::docs
