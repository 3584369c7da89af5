// Test helper: reads a KVN CDM and writes it as XML (for the independent-reader check).
#include <fstream>
#include <iostream>
#include <sstream>

#include "evade/ccsds/cdm_kvn.hpp"
#include "evade/ccsds/cdm_xml.hpp"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: cdm_to_xml IN.cdm OUT.xml\n";
    return 2;
  }
  std::ifstream in(argv[1]);
  std::ostringstream os;
  os << in.rdbuf();
  std::ofstream(argv[2]) << evade::ccsds::write_cdm_xml(
      evade::ccsds::read_cdm_kvn(os.str()));
  return 0;
}
