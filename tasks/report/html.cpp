#include "tasks/report/html.hpp"

#include "tasks/report.hpp"

namespace tasks {

std::string urlPath(const std::string& name) {
  const char* hex = "0123456789ABCDEF";
  std::string out;
  for (const unsigned char c : name) {
    const bool kept = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') ||
                      c == '-' || c == '.' || c == '_' || c == '~' || c == '/';
    if (kept)
      out += static_cast<char>(c);
    else
      out += {'%', hex[c >> 4], hex[c & 15]};
  }
  return out;
}

namespace report {

std::string escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string url(const std::string& file) {
  return escape(urlPath(file));
}

bool endsWith(const std::string& s, const std::string& suffix) {
  return s.size() > suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

void writeFigure(std::ostream& out, const std::string& file, const std::string& caption,
                 const char* loading) {
  const std::string text = caption.empty() ? file : caption;
  out << "<figure><a href=\"" << url(file) << "\"><img src=\"" << url(file) << "\" alt=\""
      << escape(text) << "\" loading=\"" << loading << "\"></a><figcaption>" << escape(text)
      << (caption.empty() ? "" : " (<a href=\"" + url(file) + "\">" + escape(file) + "</a>)")
      << "</figcaption></figure>\n";
}

}  // namespace report
}  // namespace tasks
