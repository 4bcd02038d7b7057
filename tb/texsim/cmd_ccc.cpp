// `texsim ccc`: placeholder replaced below.
#include "texsim/commands.hpp"
namespace tmu::texsim {
void add_ccc_command(CLI::App&, ExitCode&) {}
}  // namespace tmu::texsim
