// Exits with the status given as its only argument; the VM harness must pass it through.
#include <cstdio>
#include <cstdlib>

int main(int argc, char** argv) {
  const int status = argc > 1 ? std::atoi(argv[1]) : 0;
  std::printf("exit_with_status: exiting with %d\n", status);
  return status;
}
