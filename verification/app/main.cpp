#include <iostream>
#include "hm/verification/version.hpp"
int main() { std::cout << "hmlattice " << hm::verification::version() << "\n"; }
