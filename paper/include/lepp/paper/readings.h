// SPDX-License-Identifier: GPL-3.0-or-later
// Alternative readings of the problems whose geometry the paper does not pin
// down (Circles240, Rectangle162): each is a .poly in ROOT/paper/readings/,
// named PROBLEM-WHAT.poly, its first line a comment saying what it reads
// (made by paper/make_readings.py).
#pragma once
#include <string>
#include <vector>

namespace lepp::paper {

struct Reading {
  std::string problem;      // the corpus key before the first '-'
  std::string stem;         // file name without .poly
  std::string path;
  std::string description;  // the first comment line without its "# " and what precedes its first ": "
};

// Sorted by stem; empty when the folder is missing.
std::vector<Reading> find_readings(const std::string& root);

}  // namespace lepp::paper
