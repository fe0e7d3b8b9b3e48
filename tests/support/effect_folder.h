// A fresh temporary folder of effect files for a test, removed at the end of the test.
#pragma once
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace fx::testing {

class EffectFolder {
 public:
  // `name` keeps the folders of tests running at once apart (with the process id).
  explicit EffectFolder(const std::string& name)
      : root_(std::filesystem::path(::testing::TempDir()) / ("fxkit_" + name + "_" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(root_);
    std::filesystem::create_directories(root_);
  }
  ~EffectFolder() { std::filesystem::remove_all(root_); }
  EffectFolder(const EffectFolder&) = delete;
  EffectFolder& operator=(const EffectFolder&) = delete;

  // Writes `text` to the file `name` below the folder (creating its folders).
  void write(const std::string& name, const std::string& text) const {
    std::filesystem::create_directories((root_ / name).parent_path());
    std::ofstream(root_ / name) << text;
  }
  // The path of `name` below the folder (the folder itself for "").
  std::string path(const std::string& name = "") const { return (root_ / name).string(); }

 private:
  std::filesystem::path root_;
};

}  // namespace fx::testing
