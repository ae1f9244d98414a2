#pragma once
// The simulator benchmarks' command lines: `--flag value` pairs and --help.
// Hand-parsed because the core-only build (the lent GPU machines) has no
// CLI11; one parser serves every benchmark.
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <map>
#include <string>

namespace dp::bench {

class BenchArguments {
 public:
  explicit BenchArguments(std::string program) : program_(std::move(program)) {}

  BenchArguments& add(const std::string& flag, const std::string& meta, int* target) {
    return add_setter(flag, meta, [target](const char* v) { *target = std::atoi(v); });
  }
  BenchArguments& add(const std::string& flag, const std::string& meta, long* target) {
    return add_setter(flag, meta, [target](const char* v) { *target = std::atol(v); });
  }
  BenchArguments& add(const std::string& flag, const std::string& meta, double* target) {
    return add_setter(flag, meta, [target](const char* v) { *target = std::atof(v); });
  }
  BenchArguments& add(const std::string& flag, const std::string& meta, std::string* target) {
    return add_setter(flag, meta, [target](const char* v) { *target = v; });
  }

  // Exits 0 after --help, 2 on an unknown flag or a missing value.
  void parse(int argc, char** argv) const {
    for (int i = 1; i < argc; ++i) {
      const std::string flag = argv[i];
      const auto option = setters_.find(flag);
      if (option == setters_.end()) {
        std::fprintf(stderr, "usage: %s%s\n", program_.c_str(), usage_.c_str());
        std::exit(flag == "--help" ? 0 : 2);
      }
      if (i + 1 >= argc) {
        std::fprintf(stderr, "%s: %s needs a value\n", program_.c_str(), flag.c_str());
        std::exit(2);
      }
      option->second(argv[++i]);
    }
  }

 private:
  BenchArguments& add_setter(const std::string& flag, const std::string& meta, std::function<void(const char*)> set) {
    setters_[flag] = std::move(set);
    usage_ += " [" + flag + " " + meta + "]";
    return *this;
  }

  std::string program_, usage_;
  std::map<std::string, std::function<void(const char*)>> setters_;
};

}  // namespace dp::bench
