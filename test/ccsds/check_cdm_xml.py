"""Independent reader check: parse the CDM XML that evade writes with the PyPI package
ccsds-ndm (xsdata bindings of the CCSDS NDM/XML schemas) and compare key values with the KVN
source. Exit 77 (ctest: skipped) when ccsds-ndm is not installed (scripts/setup installs it)."""
import sys

try:
    from ccsds_ndm.ndm_io import NdmIo
except ImportError:
    print("SKIP: the PyPI package ccsds-ndm is not installed (scripts/setup installs it)")
    sys.exit(77)

xml_path = sys.argv[1]
cdm = NdmIo().from_path(xml_path)
rel = cdm.body.relative_metadata_data
seg = cdm.body.segment
checks = [
    ("TCA", str(rel.tca), "2000-01-01T00:00:00"),
    ("MISS_DISTANCE", float(rel.miss_distance.value), 5.049717),
    ("OBJECT2", str(seg[1].metadata.object_value.value), "OBJECT2"),
    ("X", float(seg[0].data.state_vector.x.value), 153.446765),
    ("CT_T", float(seg[1].data.covariance_matrix.ct_t.value), 6.496894829253188e03),
    ("MASS", float(seg[1].data.additional_parameters.mass.value), 500.0),
]
bad = 0
for name, got, want in checks:
    ok = (got.startswith(want) if isinstance(want, str) else abs(got - want) <= 1e-12 * abs(want))
    print(f"{name}: {got} ({'ok' if ok else 'expected ' + str(want)})")
    bad += not ok
sys.exit(1 if bad else 0)
