// The report page's HTML pieces: text escaped for HTML, file names as URLs, a captioned figure.
#pragma once

#include <ostream>
#include <string>

namespace tasks {

/// A file's name (or a path relative to the page, '/' between folders) as a relative URL's path:
/// each byte but the unreserved ones (RFC 3986: A-Z a-z 0-9 - . _ ~) and '/' as %XX. The browser
/// reads "my top #1.png" as "my top" and a fragment, and a '%' or '?' in a name breaks it alike.
std::string urlPath(const std::string& name);

}  // namespace tasks

namespace tasks::report {

/// Text for HTML: & < > " as entities.
std::string escape(const std::string& text);

/// A file's name as an attribute's URL (href, src, poster): percent-encoded (tasks::urlPath),
/// then escaped. Its visible text (a caption, a heading) stays as escape() alone writes it.
std::string url(const std::string& file);

/// Whether `s` ends with `suffix` and is longer than it.
bool endsWith(const std::string& s, const std::string& suffix);

/// An image linked to itself, captioned (its file name when there is no caption), with the
/// caption as its alt text: a bare file name tells a reader nothing of what the still shows.
void writeFigure(std::ostream& out, const std::string& file, const std::string& caption,
                 const char* loading = "eager");

/// A video, captioned, with the page's own controls in a bar below it (play, time, full screen:
/// kVideoScript wires them), so that nothing covers the picture's read-outs and inset, which
/// the browser's controls, drawn over the video's bottom, did. Without scripts the browser's
/// own controls stay. `preload`: "auto" or "metadata"; `poster`: a URL, or "" for none.
void writeVideoFigure(std::ostream& out, const std::string& file, const std::string& poster,
                      const char* preload, const std::string& caption);

/// The page's script for writeVideoFigure's bars: a classic script (the page may be opened
/// from disk), run once at the end of the page.
extern const char* const kVideoScript;
/// Their style.
extern const char* const kVideoStyle;

}  // namespace tasks::report
