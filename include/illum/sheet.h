// Pictures side by side, labelled: the comparison sheets of `illum compare` and `illum history`.
// A sheet is a grid of panels under a title, with a label over each column and beside each row,
// and under each panel an optional caption of one or more lines; labels are real text (DejaVu
// Sans, as scene labels). Every panel is copied into the sheet pixel for pixel, unscaled.
#pragma once

#include <illum/image.h>

#include <string>
#include <vector>

namespace illum {

struct SheetPanel {
  Image image;          // empty (0×0): the cell stays blank
  std::string caption;  // under the panel; '\n' separates lines
};

struct Sheet {
  std::string title;                     // over everything; empty: none
  std::string subtitle;                  // under the title, smaller (what every panel shares); empty: none
  std::string corner;                    // over the row labels (what the rows and columns are)
  std::vector<std::string> rowLabels;    // beside each row; empty: no label column
  std::vector<std::string> columnLabels; // over each column; empty: no label row
  std::vector<std::vector<SheetPanel>> panels;  // rows of panels
};

// Where everything lands: a panel's top-left corner in the sheet image.
struct SheetLayout {
  int width = 0, height = 0;
  int cellWidth = 0, cellHeight = 0;   // the largest panel's size; smaller panels are centred
  std::vector<std::vector<std::pair<int, int>>> panelOrigin;  // [row][column] → (x, y)
};
SheetLayout layoutSheet(const Sheet& sheet);

Image composeSheet(const Sheet& sheet);

// Where two pictures differ: the largest channel difference of each pixel on a colour scale from
// black (equal) through purple and orange to pale yellow (the largest difference found; by the
// square root of the difference, so that small ones show), with
// the scale drawn in its lower left corner; and the figures.
struct DifferencePanel {
  Image image;
  int maxError = 0;  // 0..255
  double psnr = 0;   // dB over RGB; +inf for identical pictures
};
DifferencePanel differencePanel(const Image& a, const Image& b);

}  // namespace illum
