#include "harness/html_report.h"

#include <gtest/gtest.h>

namespace prism::harness {
namespace {

TEST(HtmlReport, EscapesTheFiveMarkupCharactersAndNothingElse) {
  EXPECT_EQ(htmlEscape(R"(a < b && "c" > d)"), "a &lt; b &amp;&amp; &quot;c&quot; &gt; d");
  EXPECT_EQ(htmlEscape("ΔE00 0–5, it's fine"), "ΔE00 0–5, it's fine");  // UTF-8 and ' untouched
  EXPECT_EQ(htmlEscape("&amp;"), "&amp;amp;");  // text, not markup: escaped again
  EXPECT_EQ(htmlLink("#a\"b", "x<y"), "<a href=\"#a&quot;b\">x&lt;y</a>");
}

TEST(HtmlReport, PageEscapesTextButKeepsTheCallersMarkup) {
  HtmlPage page("A <title>");
  page.paragraph("<code>prism demo</code>");
  page.list({"spheres_d65: mean 0.6 > 0.5"}, "fail");
  page.table({"scene", "mean"}, {{htmlEscape("a&b"), "0.50"}});
  page.beginSection("id\"", "sky & sea");
  page.figure({{"x.png", "alt \"x\""}, {"y.png", "y", 320}}, "caption <1>");
  page.endSection();
  const std::string html = page.html();
  EXPECT_EQ(html.rfind("<!doctype html>\n", 0), 0u);
  EXPECT_NE(html.find("<title>A &lt;title&gt;</title>"), std::string::npos);
  EXPECT_NE(html.find("<h1>A &lt;title&gt;</h1>"), std::string::npos);
  EXPECT_NE(html.find("<p><code>prism demo</code></p>"), std::string::npos);
  EXPECT_NE(html.find("<li class=\"fail\">spheres_d65: mean 0.6 &gt; 0.5</li>"), std::string::npos);
  EXPECT_NE(html.find("<tr><th>scene</th><th>mean</th></tr>\n<tr><td>a&amp;b</td><td>0.50</td></tr>"),
            std::string::npos);
  EXPECT_NE(html.find("<section id=\"id&quot;\"><h2>sky &amp; sea</h2>"), std::string::npos);
  EXPECT_NE(html.find("<figure><img src=\"x.png\" alt=\"alt &quot;x&quot;\"><br><img src=\"y.png\" width=\"320\" "
                      "alt=\"y\"><figcaption>caption &lt;1&gt;</figcaption></figure>"),
            std::string::npos);
  EXPECT_EQ(html.substr(html.size() - 15), "</body></html>\n");
}

}  // namespace
}  // namespace prism::harness
