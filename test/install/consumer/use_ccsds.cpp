// evade::ccsds: the catalog form is told from the text.
#include <cstdio>

#include <evade/ccsds/catalog_formats.hpp>

int main() {
  if (evade::ccsds::detect_catalog_format("CCSDS_OMM_VERS = 2.0\n") !=
      evade::ccsds::CatalogFormat::kOmmKvn)
    return 1;
  std::printf("ccsds ok\n");
  return 0;
}
