import json, math, sys
for line in sys.stdin:
    x, = json.loads(line)
    print(math.sqrt(x + 1) - math.sqrt(x), flush=True)
