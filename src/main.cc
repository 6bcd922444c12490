// The `simhuman` executable: everything lives in the app module.
#include "simhuman/app/cli.h"

int main(int argc, char** argv) { return simhuman::app::Main(argc, argv); }
