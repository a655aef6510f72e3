#include "app/suggest.hpp"

#include <algorithm>
#include <vector>

namespace app {

std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::string explainParseError(const CLI::App& cli, int argc, char** argv, const std::string& what) {
  if (argc < 2 || argv[1][0] == '-') return what + " (see rattleback --help)";
  const std::string word = argv[1];
  std::string nearest;
  std::size_t best = 0;
  bool known = false;
  for (const CLI::App* sub : cli.get_subcommands([](const CLI::App*) { return true; })) {
    const std::string name = sub->get_name();
    if (name == word) known = true;
    const std::size_t d = editDistance(word, name);
    if (nearest.empty() || d < best) nearest = name, best = d;
  }
  if (known) return what + " (see rattleback " + word + " --help)";
  std::string line = "'" + word + "' is not a command";
  if (!nearest.empty() && best <= std::max<std::size_t>(2, word.size() / 3))
    line += "; did you mean '" + nearest + "'?";
  std::string names;
  for (const CLI::App* sub : cli.get_subcommands([](const CLI::App*) { return true; }))
    names += (names.empty() ? "" : ", ") + sub->get_name();
  return line + " (commands: " + names + "; see --help)";
}

}  // namespace app
