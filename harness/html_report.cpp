#include "harness/html_report.h"

#include <fmt/format.h>

namespace prism::harness {
namespace {

constexpr std::string_view kStyle =
    "body{font-family:sans-serif;background:#222;color:#ddd;margin:2em}"
    "figure{display:inline-block;margin:0 1em 1em 0;vertical-align:top}img{max-width:100%}"
    "figcaption{text-align:center}section{margin-bottom:2.5em}td,th{padding:0 1em;text-align:right}"
    ".fail{color:#f66}";

std::string classAttribute(std::string_view cssClass) {
  return cssClass.empty() ? std::string() : fmt::format(" class=\"{}\"", htmlEscape(cssClass));
}

std::string imageTag(const HtmlImage& image) {
  return fmt::format("<img src=\"{}\"{} alt=\"{}\">", htmlEscape(image.src),
                     image.width > 0 ? fmt::format(" width=\"{}\"", image.width) : std::string(),
                     htmlEscape(image.alt));
}

}  // namespace

std::string htmlEscape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '&') out += "&amp;";
    else if (c == '"') out += "&quot;";
    else out += c;
  }
  return out;
}

std::string htmlLink(std::string_view href, std::string_view text) {
  return fmt::format("<a href=\"{}\">{}</a>", htmlEscape(href), htmlEscape(text));
}

HtmlPage::HtmlPage(std::string_view title) {
  mHtml = fmt::format("<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<title>{0}</title>\n"
                      "<style>{1}</style></head><body>\n<h1>{0}</h1>\n",
                      htmlEscape(title), kStyle);
}

void HtmlPage::paragraph(std::string_view html, std::string_view cssClass) {
  mHtml += fmt::format("<p{}>{}</p>\n", classAttribute(cssClass), html);
}

void HtmlPage::list(const std::vector<std::string>& items, std::string_view cssClass) {
  mHtml += "<ul>\n";
  for (const std::string& item : items) mHtml += fmt::format("<li{}>{}</li>\n", classAttribute(cssClass), htmlEscape(item));
  mHtml += "</ul>\n";
}

void HtmlPage::table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows) {
  mHtml += "<table><tr>";
  for (const std::string& cell : header) mHtml += fmt::format("<th>{}</th>", cell);
  mHtml += "</tr>\n";
  for (const std::vector<std::string>& row : rows) {
    mHtml += "<tr>";
    for (const std::string& cell : row) mHtml += fmt::format("<td>{}</td>", cell);
    mHtml += "</tr>\n";
  }
  mHtml += "</table>\n";
}

void HtmlPage::beginSection(std::string_view id, std::string_view heading) {
  mHtml += fmt::format("<section{}><h2>{}</h2>\n", id.empty() ? std::string() : fmt::format(" id=\"{}\"", htmlEscape(id)),
                       htmlEscape(heading));
}

void HtmlPage::endSection() { mHtml += "</section>\n"; }

void HtmlPage::figure(const std::vector<HtmlImage>& images, std::string_view caption) {
  mHtml += "<figure>";
  for (std::size_t i = 0; i < images.size(); ++i) mHtml += (i ? "<br>" : "") + imageTag(images[i]);
  mHtml += fmt::format("<figcaption>{}</figcaption></figure>\n", htmlEscape(caption));
}

void HtmlPage::image(const HtmlImage& image) { mHtml += imageTag(image) + "\n"; }

void HtmlPage::lineBreak() { mHtml += "<br>\n"; }

std::string HtmlPage::html() const { return mHtml + "</body></html>\n"; }

}  // namespace prism::harness
