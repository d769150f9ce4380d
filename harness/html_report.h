// The HTML pages that Prism's experiments write beside their images (`prism validate`'s
// report, `prism demo`'s gallery): one look (dark page, figures side by side, right-aligned
// number tables) and one escaping rule, so a scene's description or a broken bound's "a > b"
// cannot break the markup. Text arguments are escaped; arguments named `html` are markup the
// caller built (escape what goes into it with htmlEscape).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace prism::harness {

// & < > " as entities: safe in element text and in double-quoted attributes.
std::string htmlEscape(std::string_view text);

// <a href="#id">text</a>.
std::string htmlLink(std::string_view href, std::string_view text);

struct HtmlImage {
  std::string src;  // relative to the page
  std::string alt;
  int width = 0;    // CSS pixels; 0: the image's own
};

class HtmlPage {
 public:
  explicit HtmlPage(std::string_view title);  // the head, the style and the title as <h1>

  void paragraph(std::string_view html, std::string_view cssClass = {});
  void list(const std::vector<std::string>& items, std::string_view cssClass = {});
  // A row of header cells, then rows of cells (markup: escape text with htmlEscape).
  void table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows);
  // <section id="id"><h2>heading</h2>; id may be empty.
  void beginSection(std::string_view id, std::string_view heading);
  void endSection();
  // Images stacked in one figure, with a caption below.
  void figure(const std::vector<HtmlImage>& images, std::string_view caption);
  void image(const HtmlImage& image);  // without a figure
  void lineBreak();

  // The page, closed.
  std::string html() const;

 private:
  std::string mHtml;
};

}  // namespace prism::harness
