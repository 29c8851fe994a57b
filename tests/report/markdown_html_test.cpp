// HTML from report.md's Markdown subset: each construct, escaping, heading ids, closed tags.
#include "report/markdown_html.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "html_checks.h"

namespace swingsim {
namespace {

using testing::checkTagsBalanced;
using ::testing::HasSubstr;

TEST(MarkdownHtml, RendersTheReportsSubsetAndEscapesText) {
  const std::string html = renderMarkdownHtml(
      "# A <b> & c\n\n## A b c\n\npara **bold** *it* and `x<y`\nsecond line\n\n- one\n- two\n\n| h1 | h2 |\n| --- | "
      "--- |\n| 1 | 2 |\n\n"
      "```\ncode <here>\n```\n![alt text](figures/a.svg)\n");
  EXPECT_THAT(html, HasSubstr("<h1 id=\"a-b-c\">A &lt;b&gt; &amp; c</h1>"));
  EXPECT_THAT(html, HasSubstr("<h2 id=\"a-b-c-2\">A b c</h2>"));
  EXPECT_THAT(html, HasSubstr("<p>para <strong>bold</strong> <em>it</em> and <code>x&lt;y</code>\nsecond line</p>"));
  EXPECT_THAT(html, HasSubstr("<ul>\n<li>one</li>\n<li>two</li>\n</ul>"));
  EXPECT_THAT(html,
              HasSubstr("<thead><tr><th>h1</th><th>h2</th></tr></thead>\n<tbody>\n<tr><td>1</td><td>2</td></tr>"));
  EXPECT_THAT(html, HasSubstr("<pre><code>code &lt;here&gt;\n</code></pre>"));
  EXPECT_THAT(html, HasSubstr("<p>alt text</p>"));
  EXPECT_EQ(checkTagsBalanced(html), "");
}

}  // namespace
}  // namespace swingsim
