"""Write the load benches' request bodies into a folder (argument 1):
solve.json ({"session", "options"} for POST /api/v1/solve) and session.json
(the session alone, for POST /api/v1/sessions), from the two-plane pump example."""
import json
import sys

ex = json.load(open("tests/data/examples/pump-two-plane-exact.json"))
json.dump({"session": ex["session"], "options": ex["options"]}, open(sys.argv[1] + "/solve.json", "w"))
json.dump(ex["session"], open(sys.argv[1] + "/session.json", "w"))
