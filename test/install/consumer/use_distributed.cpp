// evade::distributed: whether the package was built with MPI (its link interface carries MPI
// when it was: the package config must find it).
#include <cstdio>

#include <evade/distributed/mpi_session.hpp>

int main() {
  std::printf("distributed ok (MPI %s)\n", evade::distributed::MpiSession::built_with_mpi() ? "on" : "off");
  return 0;
}
