#pragma once
// Scenes: the parameters of one experiment run, from a TOML file plus
// `--set key=value` overrides, validated against the experiment's schema
// before any work is done. Every key is required (its one default lives in
// the scene file); unknown keys, wrong types and out-of-range values are
// rejected with a SceneError naming the key, the value and what is allowed.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>
#include <toml++/toml.h>

namespace geomint {

struct SceneError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// An interval constraint on a number; NaN and infinities never satisfy it.
struct Bound {
  std::optional<double> gt, ge, lt, le;
  bool admits(double v) const;
  std::string describe() const;  // e.g. "a finite number > 0"
};
inline Bound positive() { return {.gt = 0.0, .ge = {}, .lt = {}, .le = {}}; }
inline Bound non_negative() { return {.gt = {}, .ge = 0.0, .lt = {}, .le = {}}; }
inline Bound any_finite() { return {}; }
inline Bound at_least(double lo) { return {.gt = {}, .ge = lo, .lt = {}, .le = {}}; }

class Schema {
 public:
  enum class Type { real, integer, reals, real_rows, boolean, text, texts };
  struct Entry {
    std::string key;
    Type type;
    Bound bound;                       // numbers (each element for lists)
    std::size_t min_len = 0;           // lists: at least this many entries
    std::size_t row_len = 0;           // real_rows: every row has this many numbers
    std::vector<std::string> choices;  // text: the allowed values (empty: any)
    std::string doc;
  };

  Schema& real(std::string key, Bound b, std::string doc = {});
  Schema& integer(std::string key, Bound b, std::string doc = {});
  Schema& reals(std::string key, Bound each, std::size_t min_len, std::string doc = {});
  Schema& real_rows(std::string key, std::size_t row_len, Bound each, std::size_t min_rows, std::string doc = {});
  Schema& boolean(std::string key, std::string doc = {});
  Schema& text(std::string key, std::vector<std::string> choices, std::string doc = {});
  Schema& texts(std::string key, std::vector<std::string> choices, std::size_t min_len, std::string doc = {});

  const Entry* find(std::string_view key) const;
  const std::vector<Entry>& entries() const { return entries_; }

 private:
  Schema& add(Entry e);
  std::vector<Entry> entries_;
};

class Scene {
 public:
  // Loads `file`, applies the `key=value` overrides (values in TOML syntax:
  // 0.1, 1e-3, [0.1, 0.05], true, "text"), and validates against `schema`.
  static Scene load(const std::filesystem::path& file, const std::vector<std::string>& overrides,
                    const Schema& schema);

  double real(std::string_view key) const;
  std::int64_t integer(std::string_view key) const;
  std::vector<double> reals(std::string_view key) const;
  std::vector<std::vector<double>> real_rows(std::string_view key) const;
  bool boolean(std::string_view key) const;
  std::string text(std::string_view key) const;
  std::vector<std::string> texts(std::string_view key) const;

  // For checks that involve several keys: throws the SceneError for `key`.
  [[noreturn]] void reject(std::string_view key, std::string_view allowed) const;

  nlohmann::ordered_json to_json() const;  // the scene as resolved after overrides
  const std::filesystem::path& file() const { return file_; }

 private:
  toml::node_view<const toml::node> at(std::string_view key) const;
  std::filesystem::path file_;
  toml::table table_;
  std::vector<std::string> overridden_;
};

}  // namespace geomint
