"""Where the plastic_ccx benches write: bench/results/NAME.md (the table, also printed) and NAME.json."""
import json
import os

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def write(name, text, rows):
    res = os.path.join(ROOT, "bench", "results")
    os.makedirs(res, exist_ok=True)
    with open(os.path.join(res, name + ".md"), "w") as f:
        f.write(text)
    with open(os.path.join(res, name + ".json"), "w") as f:
        json.dump(rows, f, indent=1)
    print(text)
