// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The benchmarks' tables on stdout: columns declared once (header, width,
// decimals), rows printed cell by cell under them, so that a header and its
// values cannot drift apart.

#ifndef VVM_BENCHMARK_TABLE_H
#define VVM_BENCHMARK_TABLE_H

#include <cstddef>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace vvm_benchmark {

class Table
{
public:
  struct Column
  {
    std::string header;
    int width;
    int decimals = -1; // numbers with this many decimals; -1: whole numbers and text
    bool left = false; // left-aligned (names)
  };

  // One cell: text, a whole number, a number printed with its column's decimals, or "-" (none).
  class Cell
  {
  public:
    Cell() : kind_(NONE) {}
    Cell(std::string text) : kind_(TEXT), text_(std::move(text)) {}
    Cell(const char* text) : kind_(TEXT), text_(text) {}
    Cell(std::size_t n) : kind_(NUMBER), number_(double(n)), whole_(true) {}
    Cell(int n) : kind_(NUMBER), number_(double(n)), whole_(true) {}
    Cell(double x) : kind_(NUMBER), number_(x) {}
    static Cell none() { return Cell(); }

    std::string format(const Column& c) const
    {
      std::string s;
      if(kind_ == TEXT) s = text_;
      else if(kind_ == NONE) s = "-";
      else {
        char buffer[64];
        if(whole_ || c.decimals < 0) std::snprintf(buffer, sizeof buffer, "%.0f", number_);
        else std::snprintf(buffer, sizeof buffer, "%.*f", c.decimals, number_);
        s = buffer;
      }
      const std::size_t width = std::size_t(c.width);
      if(s.size() >= width) return s;
      const std::string pad(width - s.size(), ' ');
      return c.left ? s + pad : pad + s;
    }

  private:
    enum Kind { NONE, TEXT, NUMBER } kind_;
    std::string text_;
    double number_ = 0;
    bool whole_ = false;
  };

  explicit Table(std::vector<Column> columns) : columns_(std::move(columns)) {}

  void print_header() const
  {
    std::vector<Cell> headers;
    for(const Column& c : columns_) headers.emplace_back(c.header);
    print_row(headers);
  }

  void print_row(const std::vector<Cell>& cells) const
  {
    if(cells.size() != columns_.size())
      throw std::logic_error("a table row of " + std::to_string(cells.size()) + " cells under " +
                             std::to_string(columns_.size()) + " columns");
    std::string line;
    for(std::size_t i = 0; i < cells.size(); ++i) line += (i ? " " : "") + cells[i].format(columns_[i]);
    std::printf("%s\n", line.c_str());
    std::fflush(stdout);
  }

private:
  std::vector<Column> columns_;
};

} // namespace vvm_benchmark

#endif // VVM_BENCHMARK_TABLE_H
