// tunnelmap-cli entry point (placeholder while commands land).
#include <iostream>
int main() { std::cout << "tunnelmap-cli\n"; return 0; }
