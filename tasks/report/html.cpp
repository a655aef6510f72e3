#include "tasks/report/html.hpp"

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

void writeVideoFigure(std::ostream& out, const std::string& file, const std::string& poster,
                      const char* preload, const std::string& caption) {
  out << "<figure class=\"vid\"><video src=\"" << url(file)
      << "\" muted loop playsinline controls preload=\"" << preload << "\""
      << (poster.empty() ? "" : " poster=\"" + url(poster) + "\"")
      << "></video><div class=\"vbar\" hidden><button type=\"button\" class=\"vplay\">"
         "▶ Play</button><input type=\"range\" class=\"vseek\" min=\"0\" max=\"1\" "
         "step=\"any\" value=\"0\" aria-label=\"time (s)\"><span class=\"vtime\">0.00 s"
         "</span><button type=\"button\" class=\"vfull\">Full screen</button></div>"
         "<figcaption>"
      << caption << "</figcaption></figure>\n";
}

// The bar and caption are as wide as the video above them (a narrow video's slider and Full
// screen button otherwise ran on across the page): the figure's one column is the video's own
// width, at most the figure's, and the bar and caption, contained, do not widen it. Its rows
// keep their own heights (align-content: start): two figures side by side are stretched to the
// taller one's height, and a stretched grid shares the extra among its rows, which moved the
// shorter caption's bar down out of line with its neighbour's.
const char* const kVideoStyle = R"(
figure.vid{display:grid;grid-template-columns:minmax(0,max-content);align-content:start}
figure.vid>.vbar,figure.vid>figcaption{contain:inline-size}
.vbar{display:flex;gap:.4em;align-items:center;margin:.3em 0 .2em;font-size:.9em}
.vbar button{font:inherit;padding:.1em .6em;white-space:nowrap}.vseek{flex:1 1 auto;min-width:60px}
.vtime{font-family:"DejaVu Sans Mono",monospace;min-width:5.5em;text-align:right}
figure.vid:fullscreen{background:#000;display:flex;flex-direction:column;justify-content:center;margin:0;padding:1em;box-sizing:border-box}
figure.vid:fullscreen video{max-height:calc(100vh - 5em);width:auto;max-width:100%;margin:0 auto;background:#000}
figure.vid:fullscreen .vbar,figure.vid:fullscreen figcaption{color:#eee}
)";

// The bars replace the browser's controls, which lie over the video's bottom edge where the
// inset and the floor's scale are drawn (docs/commands.md "rattleback report"); a click on the
// picture plays or pauses, as the browser's own does.
const char* const kVideoScript = R"(
document.querySelectorAll('figure.vid').forEach(function (f) {
  var v = f.querySelector('video'), bar = f.querySelector('.vbar');
  var play = bar.querySelector('.vplay'), seek = bar.querySelector('.vseek');
  var time = bar.querySelector('.vtime'), full = bar.querySelector('.vfull');
  v.removeAttribute('controls');
  bar.hidden = false;
  function toggle() { if (v.paused) v.play().catch(function () {}); else v.pause(); }
  function shown() {
    play.textContent = v.paused ? '\u25b6 Play' : '\u275a\u275a Pause';
    time.textContent = v.currentTime.toFixed(2) + ' s';
    if (v.duration > 0 && document.activeElement !== seek) seek.value = v.currentTime / v.duration;
  }
  play.addEventListener('click', toggle);
  v.addEventListener('click', toggle);
  ['play', 'pause', 'timeupdate', 'seeked', 'loadedmetadata'].forEach(function (e) {
    v.addEventListener(e, shown);
  });
  seek.addEventListener('input', function () {
    if (v.duration > 0) v.currentTime = seek.value * v.duration;
  });
  full.addEventListener('click', function () {
    if (document.fullscreenElement) document.exitFullscreen();
    else if (f.requestFullscreen) f.requestFullscreen().catch(function () {});
  });
});
)";

}  // namespace report
}  // namespace tasks
