// The sub-commands of gab; each takes the arguments after its name.
#pragma once

namespace gab {
namespace cli {

int run_factor(int argc, char** argv);
int run_study(int argc, char** argv);
int run_diff(int argc, char** argv);
int run_compress(int argc, char** argv);
int run_decompress(int argc, char** argv);
int run_info(int argc, char** argv);
int run_demo(int argc, char** argv);

}  // namespace cli
}  // namespace gab
