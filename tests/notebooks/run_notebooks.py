"""Executes every example notebook (examples/notebooks/*.ipynb) with nbclient, as Jupyter would,
each in a scratch folder; an error in any cell (an exception, a failed assert) fails the test.

Usage: run_notebooks.py NOTEBOOK_FOLDER   (the kernel imports hyst from PYTHONPATH)
"""

import sys
import tempfile
import time
from pathlib import Path

import nbformat
from nbclient import NotebookClient
from nbclient.exceptions import CellExecutionError

folder = Path(sys.argv[1])
notebooks = sorted(folder.glob("*.ipynb"))
if len(notebooks) < 3:
    sys.exit(f"FAIL: expected the three example notebooks in {folder}, found {len(notebooks)}")
failed = []
for path in notebooks:
    notebook = nbformat.read(path, as_version=4)
    start = time.perf_counter()
    with tempfile.TemporaryDirectory() as scratch:
        client = NotebookClient(notebook, timeout=600, kernel_name="python3",
                                resources={"metadata": {"path": scratch}})
        try:
            client.execute()
        except CellExecutionError as error:
            failed.append(path.name)
            print(f"FAIL: {path.name}:\n{error}")
            continue
    errors = [output for cell in notebook.cells for output in cell.get("outputs", [])
              if output.get("output_type") == "error"]
    if errors:
        failed.append(path.name)
        print(f"FAIL: {path.name}: {errors[0].get('ename')}: {errors[0].get('evalue')}")
        continue
    cells = sum(cell.cell_type == "code" for cell in notebook.cells)
    print(f"{path.name}: {cells} code cells ran in {time.perf_counter() - start:.1f} s")
sys.exit(1 if failed else 0)
