#include "scene/direct_rows.hpp"

#include <charconv>
#include <cmath>
#include <string>
#include <string_view>
#include <type_traits>

#include "scene/key_path.hpp"
#include "scene/sweep.hpp"

namespace scene {
namespace {

// A numeral of digits, signs, a point and an exponent alone, read by std::from_chars: a plain
// scalar to YAML, which yaml-cpp decodes by strtod, correctly rounded as from_chars is, so the
// same double without a YAML tree (3.5 µs a value: a sweep of 200 spins spent 0.7 ms on them).
// Anything else, or a result out of range or subnormal (where the two report differently), is
// left to yaml-cpp.
std::optional<double> plainNumeral(std::string_view text) {
  if (text.empty() || text.find_first_not_of("0123456789+-.eE") != std::string_view::npos)
    return std::nullopt;
  if (text.front() == '+') text.remove_prefix(1);  // from_chars takes no '+'; strtod does
  double value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  if (value != 0 && !std::isnormal(value)) return std::nullopt;
  return value;
}

// The number the loader reads from a value's text (MapReader::number): a plain scalar, not a
// quoted string, that yaml-cpp decodes; nothing otherwise.
std::optional<double> numberIn(const std::string& text) {
  if (const std::optional<double> plain = plainNumeral(text)) return plain;
  try {
    const YAML::Node node = YAML::Load(text);
    double v = 0;
    if (node.IsScalar() && node.Tag() != "!" && YAML::convert<double>::decode(node, v)) return v;
  } catch (const YAML::Exception&) {
  }
  return std::nullopt;
}

// Whether `key` at `path` (an index or none) names one number the base tree gives: a number
// member, or an element of a list-of-numbers member whose list is there.
bool writable(const Key& key, const KeyPath& path, const YAML::Node& base) {
  const YAML::Node node = find(base, path);
  return std::visit(
      [&](auto member) {
        if constexpr (std::is_same_v<decltype(member), std::monostate>) {
          return false;
        } else {
          using Member = std::remove_reference_t<decltype(member(std::declval<Loaded&>()))>;
          if constexpr (std::is_same_v<Member, double>) {
            return !path.index && node.IsDefined();
          } else if constexpr (std::is_same_v<Member, std::array<double, 2>> ||
                               std::is_same_v<Member, std::array<double, 3>>) {
            const std::size_t n = std::tuple_size_v<Member>;
            return path.index && *path.index < n && node.IsSequence() && node.size() == n;
          } else {
            return false;
          }
        }
      },
      key.field);
}

void write(const Key& key, const std::optional<std::size_t>& index, double value, Loaded& scene) {
  std::visit(
      [&](auto member) {
        if constexpr (!std::is_same_v<decltype(member), std::monostate>) {
          auto& target = member(scene);
          using Member = std::remove_reference_t<decltype(target)>;
          if constexpr (std::is_same_v<Member, double>)
            target = value;
          else if constexpr (std::is_same_v<Member, std::array<double, 2>> ||
                             std::is_same_v<Member, std::array<double, 3>>)
            target[*index] = value;
        }
      },
      key.field);
}

}  // namespace

DirectRows DirectRows::open(const YAML::Node& base, const std::vector<SweepAxis>& axes,
                            const std::function<rb::Result<Loaded>()>& load) {
  DirectRows out;
  for (const SweepAxis& axis : axes) {
    const std::optional<KeyPath> path = splitKey(axis.key);
    const Key* key = findKey(withoutIndex(axis.key));
    if (!path || !key || !writable(*key, *path, base)) return {};
    Axis direct{key, path->index, {}};
    for (const std::string& value : axis.values) direct.numbers.push_back(numberIn(value));
    out.axes_.push_back(std::move(direct));
  }
  auto loaded = load();
  if (!loaded) return {};
  out.base_ = std::move(loaded).value();
  return out;
}

std::optional<Loaded> DirectRows::scene(const std::vector<int>& at) const {
  if (!base_) return std::nullopt;
  for (std::size_t i = 0; i < axes_.size(); ++i)
    if (!axes_[i].numbers[static_cast<std::size_t>(at[i])]) return std::nullopt;
  Loaded scene = *base_;
  for (std::size_t i = 0; i < axes_.size(); ++i)
    write(*axes_[i].key, axes_[i].index, *axes_[i].numbers[static_cast<std::size_t>(at[i])], scene);
  return scene;
}

}  // namespace scene
