#include <illum/sheet.h>

#include "image/text.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

namespace illum {
namespace {

constexpr int kMargin = 16, kGap = 10;
constexpr Real kTitleSize = 22, kLabelSize = 17, kCaptionSize = 14;
constexpr std::array<std::uint8_t, 4> kPaper = {30, 30, 32, 255};
const Vec3 kInk(0.93f, 0.93f, 0.93f), kDimInk(0.7f, 0.7f, 0.72f);

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

// A caption's lines: its own ('\n'), each broken between words where it would be wider than `width`.
std::vector<std::string> captionRows(const std::string& caption, int width) {
  std::vector<std::string> rows;
  for (const std::string& line : lines(caption)) {
    std::istringstream words(line);
    std::string row;
    for (std::string word; words >> word;) {
      const std::string longer = row.empty() ? word : row + " " + word;
      if (!row.empty() && textWidth(longer, kCaptionSize) > Real(width)) {
        rows.push_back(row);
        row = word;
      } else {
        row = longer;
      }
    }
    rows.push_back(row);
  }
  return rows;
}

int captionLines(const Sheet& sheet, int width) {
  std::size_t most = 0;
  for (const auto& row : sheet.panels)
    for (const SheetPanel& p : row) most = std::max(most, captionRows(p.caption, width).size());
  return int(most);
}

// Captions keep a few pixels from the next column's.
constexpr int kCaptionInset = 8;

int lineHeight(Real size) { return int(std::ceil(size * 1.35f)); }

}  // namespace

SheetLayout layoutSheet(const Sheet& sheet) {
  SheetLayout l;
  std::size_t columns = sheet.columnLabels.size();
  for (const auto& row : sheet.panels) {
    columns = std::max(columns, row.size());
    for (const SheetPanel& p : row) l.cellWidth = std::max(l.cellWidth, p.image.width), l.cellHeight = std::max(l.cellHeight, p.image.height);
  }
  for (const std::string& label : sheet.columnLabels)
    l.cellWidth = std::max(l.cellWidth, int(std::ceil(textWidth(label, kLabelSize))) + 8);
  int labelColumn = 0;
  for (const std::string& label : sheet.rowLabels) labelColumn = std::max(labelColumn, int(std::ceil(textWidth(label, kLabelSize))));
  if (!sheet.rowLabels.empty())
    labelColumn = std::max(labelColumn, int(std::ceil(textWidth(sheet.corner, kCaptionSize)))) + kGap + 8;
  const int top = kMargin + (sheet.title.empty() ? 0 : lineHeight(kTitleSize) + 6) +
                  (sheet.subtitle.empty() ? 0 : lineHeight(kCaptionSize) + 4) +
                  (sheet.columnLabels.empty() ? 0 : lineHeight(kLabelSize) + 4);
  const int captionCount = captionLines(sheet, l.cellWidth - kCaptionInset);
  const int captionBand = captionCount * lineHeight(kCaptionSize) + (captionCount ? 4 : 0);
  const int rows = int(sheet.panels.size());
  l.panelOrigin.resize(sheet.panels.size());
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < int(sheet.panels[std::size_t(r)].size()); ++c) {
      const Image& image = sheet.panels[std::size_t(r)][std::size_t(c)].image;
      const int x = kMargin + labelColumn + c * (l.cellWidth + kGap) + (l.cellWidth - image.width) / 2;
      const int y = top + r * (l.cellHeight + captionBand + kGap) + (l.cellHeight - image.height) / 2;
      l.panelOrigin[std::size_t(r)].push_back({x, y});
    }
  l.width = kMargin * 2 + labelColumn + int(columns) * l.cellWidth + std::max(0, int(columns) - 1) * kGap;
  l.height = top + rows * (l.cellHeight + captionBand) + std::max(0, rows - 1) * kGap + kMargin;
  if (!sheet.title.empty())
    l.width = std::max(l.width, 2 * kMargin + int(std::ceil(textWidth(sheet.title, kTitleSize))));
  if (!sheet.subtitle.empty())
    l.width = std::max(l.width, 2 * kMargin + int(std::ceil(textWidth(sheet.subtitle, kCaptionSize))));
  return l;
}

Image composeSheet(const Sheet& sheet) {
  const SheetLayout l = layoutSheet(sheet);
  Image out(l.width, l.height);
  for (std::size_t i = 0; i < out.rgba.size(); i += 4) std::copy(kPaper.begin(), kPaper.end(), out.rgba.begin() + long(i));
  int y = kMargin;
  if (!sheet.title.empty()) {
    y += lineHeight(kTitleSize);
    drawText(out, Real(l.width) / 2, Real(y - 6), sheet.title, kTitleSize, kInk);
    y += 6;
  }
  if (!sheet.subtitle.empty()) {
    y += lineHeight(kCaptionSize);
    drawText(out, Real(l.width) / 2, Real(y - 4), sheet.subtitle, kCaptionSize, kDimInk);
    y += 4;
  }
  // The first column's left edge: where the grid starts.
  int gridLeft = kMargin;
  if (!sheet.panels.empty() && !sheet.panels[0].empty())
    gridLeft = l.panelOrigin[0][0].first - (l.cellWidth - sheet.panels[0][0].image.width) / 2;
  if (!sheet.columnLabels.empty()) {
    y += lineHeight(kLabelSize);
    for (std::size_t c = 0; c < sheet.columnLabels.size(); ++c)
      drawText(out, Real(gridLeft + int(c) * (l.cellWidth + kGap)) + Real(l.cellWidth) / 2, Real(y - 5),
               sheet.columnLabels[c], kLabelSize, kInk);
    if (!sheet.corner.empty() && !sheet.rowLabels.empty())
      drawText(out, Real(kMargin + gridLeft - kGap) / 2, Real(y - 5), sheet.corner, kCaptionSize, kDimInk);
  }
  for (std::size_t r = 0; r < sheet.panels.size(); ++r) {
    const int rowTop = l.panelOrigin[r].empty() ? 0
                                                 : l.panelOrigin[r][0].second -
                                                       (l.cellHeight - sheet.panels[r][0].image.height) / 2;
    if (r < sheet.rowLabels.size())
      drawText(out, Real(kMargin + gridLeft - kGap) / 2, Real(rowTop) + Real(l.cellHeight) / 2 + kLabelSize / 3,
               sheet.rowLabels[r], kLabelSize, kInk);
    for (std::size_t c = 0; c < sheet.panels[r].size(); ++c) {
      const SheetPanel& p = sheet.panels[r][c];
      const auto [px, py] = l.panelOrigin[r][c];
      for (int j = 0; j < p.image.height; ++j)
        std::copy_n(p.image.pixel(0, j), std::size_t(p.image.width) * 4, out.pixel(px, py + j));
      int baseline = rowTop + l.cellHeight + 2;
      for (const std::string& line : captionRows(p.caption, l.cellWidth - kCaptionInset)) {
        baseline += lineHeight(kCaptionSize);
        drawText(out, Real(gridLeft + int(c) * (l.cellWidth + kGap)) + Real(l.cellWidth) / 2, Real(baseline - 4), line,
                 kCaptionSize, kDimInk);
      }
    }
  }
  return out;
}

namespace {

// The colour scale of difference panels, at t in [0, 1] (five stops, linearly between them).
Vec3 heat(Real t) {
  static const Vec3 stops[] = {{0, 0, 0}, {0.26f, 0.04f, 0.41f}, {0.73f, 0.21f, 0.33f}, {0.98f, 0.55f, 0.04f}, {0.99f, 1, 0.64f}};
  t = std::clamp(t, Real(0), Real(1)) * 4;
  const int i = std::min(3, int(t));
  return glm::mix(stops[i], stops[i + 1], t - Real(i));
}

}  // namespace

DifferencePanel differencePanel(const Image& a, const Image& b) {
  DifferencePanel d;
  const ImageDifference figures = compareImages(a, b, 0);
  d.maxError = figures.maxError;
  d.psnr = figures.psnr;
  d.image = Image(a.width, a.height);
  const Real scale = d.maxError > 0 ? Real(1) / Real(d.maxError) : 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      const std::uint8_t *p = a.pixel(x, y), *q = b.pixel(x, y);
      int e = 0;
      for (int k = 0; k < 4; ++k) e = std::max(e, std::abs(int(p[k]) - int(q[k])));
      const Vec3 c = heat(std::sqrt(Real(e) * scale));  // square root: small differences show too
      std::uint8_t* o = d.image.pixel(x, y);
      for (int k = 0; k < 3; ++k) o[k] = std::uint8_t(std::lround(c[k] * 255));
      o[3] = 255;
    }
  // The scale: a bar from 0 to the largest difference in the lower left corner.
  const int barWidth = std::min(a.width - 16, 120), barHeight = 8, x0 = 8, y0 = a.height - 26;
  if (barWidth > 20 && y0 > 8) {
    for (int y = y0 - 1; y < y0 + barHeight + 1; ++y)
      for (int x = x0 - 1; x < x0 + barWidth + 1; ++x) {
        const bool edge = y < y0 || y >= y0 + barHeight || x < x0 || x >= x0 + barWidth;
        const Vec3 c = edge ? Vec3(0.6f) : heat(std::sqrt(Real(x - x0) / Real(barWidth - 1)));
        std::uint8_t* o = d.image.pixel(x, y);
        for (int k = 0; k < 3; ++k) o[k] = std::uint8_t(std::lround(c[k] * 255));
      }
    drawText(d.image, Real(x0 + 4), Real(y0 + barHeight + 14), "0", 11, Vec3(0.9f));
    drawText(d.image, Real(x0 + barWidth - 8), Real(y0 + barHeight + 14), std::to_string(d.maxError), 11, Vec3(0.9f));
  }
  return d;
}

}  // namespace illum
