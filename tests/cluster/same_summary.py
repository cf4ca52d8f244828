"""Exit 0 if two sweep folders' summary.dat agree in every column but wall_s (each folder's
own path replaced, where a reason names it); else print both and exit 1."""
import sys


def rows(folder):
    path = folder + '/summary.dat'
    lines = open(path).read().splitlines()
    header = [l[2:].split() for l in lines if l.startswith('# ') and ' status ' in l][0]
    wall = header.index('wall_s')
    out = []
    for line in lines:
        if line.strip() and not line.startswith('#'):
            words = [w for k, w in enumerate(line.split()) if k != wall]
            out.append(' '.join(words).replace(folder, 'OUT'))
    return out


a, b = rows(sys.argv[1]), rows(sys.argv[2])
if a != b or len(a) == 0:
    print('\n'.join(['direct:'] + a + ['collected:'] + b))
    sys.exit(1)
