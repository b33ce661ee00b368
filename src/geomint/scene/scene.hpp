#pragma once
// Scenes: the parameters of one experiment run, from a TOML file plus
// `--set key=value` overrides, validated against the experiment's schema
// before any work is done.
//
// A scene may name a base scene (`base = "<file>.toml"`, relative to its own
// directory): the base is loaded first and the scene's keys are laid over it
// (tables merge key by key; any other value, lists included, replaces the
// base's). So a quick scene holds only what differs from the paper scene.
// Every key present is checked for its type and range; which keys must be
// present is decided by the studies that run (Scene::require): a parameter's
// one default lives in the paper scene.
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>  // (Scene::to_json; the runner includes the library)

#include "geomint/io/printable.hpp"  // printable(): a value or argument shown on one line

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
// A tolerance of a reference solution: tighter than 1e-15 is below round-off, looser than 1e-2 is no reference.
inline Bound tolerance() { return {.gt = {}, .ge = 1e-15, .lt = {}, .le = 1e-2}; }
// The largest count of steps or evaluations a scene may ask for: 2^53, up to which counts are exact in
// a double (steps are counted in 64-bit integers, t = n h).
inline constexpr double max_exact_count = 9007199254740992.0;
// The longest list a scene may give (step sizes, starts, rows): no study of the papers uses more than
// 17 entries, and a study runs every entry, so a longer list is a mistake or a run of hours per entry.
// A list of choices (methods) holds each choice at most once, so at most as many entries as choices.
inline constexpr std::size_t max_list_entries = 1000;

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

  // (copied, moved and destroyed in scene.cpp: compiled once, not in every study that declares keys)
  Schema();
  Schema(const Schema&);
  Schema(Schema&&) noexcept;
  Schema& operator=(const Schema&);
  Schema& operator=(Schema&&) noexcept;
  ~Schema();

  Schema& real(std::string key, Bound b, std::string doc = {});
  Schema& integer(std::string key, Bound b, std::string doc = {});
  Schema& reals(std::string key, Bound each, std::size_t min_len, std::string doc = {});
  Schema& real_rows(std::string key, std::size_t row_len, Bound each, std::size_t min_rows, std::string doc = {});
  Schema& boolean(std::string key, std::string doc = {});
  Schema& text(std::string key, std::vector<std::string> choices, std::string doc = {});
  Schema& texts(std::string key, std::vector<std::string> choices, std::size_t min_len, std::string doc = {});
  // An older spelling of a key: scene files and --set may use it, it reads as `key`.
  Schema& alias(std::string old_key, std::string key);
  Schema& declare(Entry e) { return add(std::move(e)); }  // (std::logic_error on a key declared twice)
  // Every entry and alias of `other` (std::logic_error on a key declared in both).
  Schema& merge(const Schema& other);

  const Entry* find(std::string_view key) const;
  const std::vector<Entry>& entries() const { return entries_; }
  const std::vector<std::pair<std::string, std::string>>& aliases() const { return aliases_; }

 private:
  Schema& add(Entry e);
  std::vector<Entry> entries_;
  std::vector<std::pair<std::string, std::string>> aliases_;  // (old, new)
};

// "a number", "a list of strings", ...: how --help and error messages name a type.
std::string type_name(Schema::Type t);
// What a key admits, in words: the range of a number, the choices of a string.
std::string allowed_values(const Schema::Entry& e);
// The most entries a list key admits: max_list_entries, or as many as its choices.
std::size_t max_entries(const Schema::Entry& e);

// Does `key` fall under one of `prefixes` (equal, or prefix + "." + ...)?
bool key_under(std::string_view key, const std::vector<std::string>& prefixes);

class Scene {
 public:
  // Loads `file` and its bases, applies the `key=value` overrides (values in
  // TOML syntax: 0.1, 1e-3, [0.1, 0.05], true, "text"), and checks every key
  // present against `schema` (unknown keys, types, ranges).
  static Scene load(const std::filesystem::path& file, const std::vector<std::string>& overrides,
                    const Schema& schema);

  // Every schema key under one of `prefixes` must be present; `who` names what needs it.
  void require(const std::vector<std::string>& prefixes, std::string_view who, const Schema& schema) const;
  // Reads are restricted to the keys under `prefixes` (empty: no restriction), so
  // that a study that reads a key it did not declare fails loudly.
  void restrict_reads(std::vector<std::string> prefixes, std::string who = {}) const;
  // Records the keys read from now on in `log` (each once, in the order first read); nullptr stops.
  void log_reads(std::vector<std::string>* log) const { read_log_ = log; }

  bool has(std::string_view key) const;  // a key or a section

  double real(std::string_view key) const;
  std::int64_t integer(std::string_view key) const;
  std::vector<double> reals(std::string_view key) const;
  std::vector<std::vector<double>> real_rows(std::string_view key) const;
  bool boolean(std::string_view key) const;
  std::string text(std::string_view key) const;
  std::vector<std::string> texts(std::string_view key) const;

  // For checks that involve several keys: throws the SceneError for `key`.
  [[noreturn]] void reject(std::string_view key, std::string_view allowed) const;

  nlohmann::ordered_json to_json() const;  // the scene as resolved after bases and overrides
  const std::filesystem::path& file() const { return file_; }
  const std::vector<std::filesystem::path>& bases() const { return bases_; }  // base files, nearest first

 private:
  struct Table;  // the resolved TOML table (scene.cpp): toml++ stays out of this header
  // A read of `key`: refused outside restrict_reads' prefixes, recorded in log_reads' log.
  void note_read(std::string_view key) const;
  template <class T>
  T value(std::string_view key) const;  // a number, boolean or string (scene.cpp)
  std::filesystem::path file_;
  std::vector<std::filesystem::path> bases_;
  std::shared_ptr<Table> table_;  // immutable once load() returns; copies of a Scene share it
  std::map<std::string, std::string, std::less<>> origin_;  // leaf key -> "from --set" / "in FILE"
  mutable std::vector<std::string> readable_;
  mutable std::string reader_;
  mutable std::vector<std::string>* read_log_ = nullptr;
};

}  // namespace geomint
