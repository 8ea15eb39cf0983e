#include <iostream>

#include "app/commands.hpp"

int main(int argc, char** argv) {
    return impossible::app::run_main(impossible::app::Args(argv + 1, argv + argc), std::cout, std::cerr);
}
