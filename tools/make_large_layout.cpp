// make_large_layout N OUT.json: a layout of N rooms on a grid, joined in one
// chain by coincident doors (src/design/large_layout.hpp), for
// bench/large-layouts.sh. The same N writes the same bytes.
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>

#include "design/large_layout.hpp"

int main(int argc, char** argv) {
    if (argc != 3) {
        std::cerr << "usage: make_large_layout N OUT.json\n";
        return 2;
    }
    char* end = nullptr;
    const long n = std::strtol(argv[1], &end, 10);
    if (*end != '\0' || n < 1 || n > impossible::design::kMaxLargeRooms) {
        std::cerr << "make_large_layout: N must be 1.." << impossible::design::kMaxLargeRooms << "\n";
        return 2;
    }
    std::ofstream out(argv[2], std::ios::binary);
    out << impossible::design::large_layout_text(static_cast<int>(n));
    if (!out) {
        std::cerr << "make_large_layout: cannot write " << argv[2] << "\n";
        return 1;
    }
    return 0;
}
