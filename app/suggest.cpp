#include "app/suggest.hpp"

#include <algorithm>
#include <cctype>
#include <optional>
#include <vector>

#include "scene/keys.hpp"
#include "util/nearest.hpp"

namespace app {

namespace {

// The options a command takes, spelt as typed: "--fps", "-o".
std::vector<std::string> optionNames(const CLI::App& command) {
  std::vector<std::string> names;
  for (const CLI::Option* option : command.get_options()) {
    for (const std::string& l : option->get_lnames()) names.push_back("--" + l);
    for (const std::string& s : option->get_snames()) names.push_back("-" + s);
  }
  return names;
}

// What an option takes, as the messages say it: "a number", "a whole number", "a value".
std::string takes(const CLI::Option& option) {
  const std::string type = option.get_type_name();
  return type == "INT" ? "a whole number" : type == "FLOAT" ? "a number" : "a value";
}

// An option's help up to its first parenthesis: "initial spin, rad/s".
std::string gist(const CLI::Option& option) {
  std::string text = option.get_description().substr(0, option.get_description().find(" ("));
  if (text.size() > 1 && std::islower(static_cast<unsigned char>(text[1])))
    text[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(text[0])));
  return text;
}

bool looksLikeANumber(const std::string& word) {
  return word.size() > 1 && (std::isdigit(static_cast<unsigned char>(word[1])) || word[1] == '.');
}

// The scene key whose last word is `word` (tilt: initial.tilt), or nothing.
std::string sceneKeyEndingIn(const std::string& word) {
  for (const scene::Key& key : scene::keys()) {
    const std::string_view path = key.path;
    const std::size_t dot = path.rfind('.');
    if (dot != std::string_view::npos && path.substr(dot + 1) == word) return std::string(path);
  }
  return "";
}

// The first word from argv[first] on that is none of `command`'s options, said with the nearest
// option, or nothing.
std::optional<std::string> unknownOption(const CLI::App& command, const std::string& path,
                                         int first, int argc, char** argv) {
  const std::vector<std::string> names = optionNames(command);
  auto known = [&](const std::string& name) {
    return std::find(names.begin(), names.end(), name) != names.end();
  };
  for (int i = first; i < argc; ++i) {
    std::string word = argv[i];
    if (word == "--") break;  // what follows is positional
    if (word.size() < 2 || word[0] != '-' || looksLikeANumber(word)) continue;
    word = word.substr(0, word.find('='));
    if (word[1] != '-' && word.size() > 2) {  // -qv: short flags together
      bool all = true;
      for (std::size_t c = 1; c < word.size(); ++c) all = all && known(std::string("-") + word[c]);
      if (all) continue;
    } else if (known(word)) {
      continue;
    }
    std::string line = path + ": no option " + word;
    // A one-letter option is one edit from every other: no guess for those.
    if (const auto nearest = rb::nearestWord(word, names); word.size() > 2 && nearest)
      line += "; did you mean " + *nearest + "?";
    else if (const std::string key = sceneKeyEndingIn(word.substr(
                 std::min(word.find_first_not_of('-'), word.size())));  // (--- is all dashes)
             !key.empty() && known("--set"))
      // A scene key's last word (--tilt for initial.tilt): set it as the file would have it.
      line += ": " + key + " is a scene key; --set " + key + "=VALUE puts it in";
    return line + " (see rattleback " + path + " --help)";
  }
  return std::nullopt;
}

// A known command with a word that is none of its options: the line names the word and the
// nearest option; otherwise CLI11's message and a pointer to the command's --help.
std::string explainOptionError(const CLI::App& cli, int argc, char** argv,
                               const std::string& what) {
  const CLI::App* command = cli.get_subcommand(argv[1]);
  std::string path = argv[1];
  int first = 2;
  if (argc > 2) {
    for (const CLI::App* sub : command->get_subcommands([](const CLI::App*) { return true; }))
      if (sub->get_name() == argv[2]) command = sub, path += std::string(" ") + argv[2], first = 3;
  }
  if (auto unknown = unknownOption(*command, path, first, argc, argv)) return *unknown;
  // CLI11 says "Could not convert: --dt = abc": said as what the option takes.
  const std::string prefix = "Could not convert: ", equals = " = ";
  if (const std::size_t at = what.find(equals);
      what.rfind(prefix, 0) == 0 && at != std::string::npos) {
    const std::string name = what.substr(prefix.size(), at - prefix.size());
    const std::string value = what.substr(at + equals.size());
    if (const CLI::Option* option = command->get_option_no_throw(name))
      return path + ": " + name + " takes " + takes(*option) + ", not '" + value +
             "' (see rattleback " + path + " --help)";
  }
  // CLI11 says "--spin: 1 required FLOAT missing" for an option given no value.
  if (const std::size_t at = what.find(": ");
      at != std::string::npos && what.find(" required ") != std::string::npos && what.size() > 8 &&
      what.compare(what.size() - 8, 8, " missing") == 0)
    if (const CLI::Option* option = command->get_option_no_throw(what.substr(0, at)))
      return path + ": " + what.substr(0, at) + " takes " + takes(*option) + " (" + gist(*option) +
             "), none given (see rattleback " + path + " --help)";
  // --set KEY VALUE, a space for the =: the value was "not expected".
  if (what.find("was not expected") != std::string::npos)
    for (int i = first + 1; i + 1 < argc; ++i)
      if (std::string(argv[i - 1]) == "--set" &&
          std::string(argv[i]).find('=') == std::string::npos)
        return path + ": --set takes KEY=VALUE in one word, not '" + argv[i] + "' (--set " +
               argv[i] + "=" + argv[i + 1] + ")";
  // Several KEY=VALUE words after one --set: the second was taken for the scene, and CLI11 named
  // the scene as "not expected".
  if (what.find("was not expected") != std::string::npos)
    for (int i = first + 1; i < argc; ++i)
      if (std::string(argv[i - 1]) == "--set" && i + 1 < argc &&
          std::string(argv[i + 1]).find('=') != std::string::npos && argv[i + 1][0] != '-')
        return path + ": " + argv[i + 1] +
               " follows a --set entry without a --set of its own; each KEY=VALUE takes one "
               "(--set " +
               argv[i] + " --set " + argv[i + 1] + ")";
  // CLI11 says "--dt: At Most 1 required but received 2" for an option given twice.
  const std::string twice = ": At Most 1 required but received ";
  if (const std::size_t at = what.find(twice); at != std::string::npos)
    return path + ": " + what.substr(0, at) + " given " + what.substr(at + twice.size()) +
           " times; give it once (see rattleback " + path + " --help)";
  return what + " (see rattleback " + path + " --help)";
}

}  // namespace

std::string explainParseError(const CLI::App& cli, int argc, char** argv, const std::string& what) {
  if (argc < 2 || argv[1][0] == '-') return what + " (see rattleback --help)";
  const std::string word = argv[1];
  std::vector<std::string> commands;
  for (const CLI::App* sub : cli.get_subcommands([](const CLI::App*) { return true; }))
    commands.push_back(sub->get_name());
  if (std::find(commands.begin(), commands.end(), word) != commands.end())
    return explainOptionError(cli, argc, argv, what);
  std::string line = "'" + word + "' is not a command";
  if (const auto nearest = rb::nearestWord(word, commands))
    line += "; did you mean '" + *nearest + "'?";
  std::string names;
  for (const CLI::App* sub : cli.get_subcommands([](const CLI::App*) { return true; }))
    names += (names.empty() ? "" : ", ") + sub->get_name();
  return line + " (commands: " + names + "; see --help)";
}

}  // namespace app
