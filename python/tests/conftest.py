import os
import pathlib

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
FIXTURES = ROOT / "fixtures"
DATA = pathlib.Path(os.environ.get("MOCAPFILL_DATA_DIR", ROOT.parent / "shared" / "data"))


@pytest.fixture(scope="session")
def fixtures():
    return FIXTURES


@pytest.fixture(scope="session")
def data_dir():
    if not (DATA / "bandai-namco-1").is_dir():
        pytest.skip("corpus not found at %s (../shared/data)" % DATA)
    return DATA


@pytest.fixture(scope="session")
def default_db():
    import mocapfill
    return mocapfill.Database.open("default")
