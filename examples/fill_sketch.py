#!/usr/bin/env python3
"""fill_sketch.py SKETCH OUT [DATABASE]: fills a keyframed sketch with the mocapfill Python
module (the default database when none is given) and writes the complete animation."""
import sys

import mocapfill


def main(argv):
    if len(argv) not in (3, 4):
        print("usage: fill_sketch.py SKETCH OUT [DATABASE]", file=sys.stderr)
        return 1
    try:
        sketch = mocapfill.load(argv[1])
        database = mocapfill.Database.open(argv[3] if len(argv) == 4 else None)
        scene, report = mocapfill.fill(sketch, database)
        mocapfill.save(scene, argv[2])
    except mocapfill.Error as e:
        print("error: %s" % e, file=sys.stderr)
        return e.exit_code
    clip = scene.clip(0)
    print("%s: %d joints, %d frames filled from %s (%d clips); key error max %.4f deg"
          % (argv[2], scene.joint_count, clip.frame_count, database.name, database.clip_count,
             report["key_error_max_deg"]))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
