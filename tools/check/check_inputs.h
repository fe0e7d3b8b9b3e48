// The effect files a `fxkit check PATH...` run checks: files named, and the files of named
// folders (recursively) that match the include globs and no exclude glob, less the files
// that other files found there include (checked through their includers), in path order,
// then the run's shard of them.
#pragma once
#include <string>
#include <vector>

namespace fx::tools {

struct CheckInputOptions {
  // fnmatch(3) patterns: one without '/' matches a file's name, one with '/' the path below
  // the folder named on the command line ('*' then crosses folders).
  std::vector<std::string> include_globs{"*.fx"};
  std::vector<std::string> exclude_globs;
  std::vector<std::string> include_dirs;  // -I: where #include may also resolve
  unsigned shard = 1, shards = 1;         // --shard K/N: this run checks shard K of N
};

struct CheckInputs {
  std::vector<std::string> files;  // the roots to check, sorted by path
  size_t included_only = 0;        // folder files left to their includers
  size_t other_shards = 0;         // roots another shard checks
};

// Finds the inputs; false and a message in `error` for a PATH that does not exist or a
// folder that cannot be read.
bool find_check_inputs(const std::vector<std::string>& paths, const CheckInputOptions& options, CheckInputs& out,
                       std::string& error);

// Parses "K/N" (1 <= K <= N); false for anything else.
bool parse_shard(const std::string& text, unsigned& shard, unsigned& shards);

// The shard (1..shards) a file belongs to: a hash of its path as listed, so a file stays in
// its shard when others are added or removed.
unsigned shard_of(const std::string& file, unsigned shards);

}  // namespace fx::tools
