import random, sys
def gen(seed):
    R = random.Random(seed)
    k = R.choice([1, 1e-6, 1e6, 2.0**300, 2.0**-300, 2.0**-40])
    o = R.choice([0, 0, 1e7*k if k<1 else 0, 3*k, 1e3*k])
    off = [o*R.choice([1,0,-1]) for _ in range(3)]
    def P(v): return "[%r, %r, %r]" % tuple(off[i] + k*v[i] for i in range(3))
    def S(x): return "%r" % (k*x)
    out = ["image { width 16 height 12 samples 1 max_depth 1 background 0.1 }"]
    eye = [R.uniform(-1,1), R.uniform(2,5), R.uniform(-5,-3)]
    out.append("camera { perspective eye %s look_at %s up [0, 1, 0] fov 70 }" % (P(eye), P([0,0.2,0])))
    out.append("ambient { color 0.05 }")
    ly = R.choice([0.0, 0.0, 1.0, 0.5, 1e-9, 1000.0])
    smp = R.choice([16, 64, 300, 2000])
    if R.random() < 0.5:
        nrm = R.choice(["[0, -1, 0]", "[0, 1, 0]", "[1, 0, 0]", "[0.3, -1, 0.2]"])
        out.append("distributed_light { disk %s %s %s power 5 samples %d d0 0 falloff none }" % (P([R.uniform(-1,1), ly, R.uniform(-1,1)]), nrm, S(R.choice([0.5, 2, 1e-3])), smp))
    else:
        eu = R.choice([[2,0,0],[0.01,0,0]]); ev = R.choice([[0,0,2],[0,0.5,0],[0,0,1e-4]])
        out.append("distributed_light { rectangle %s [%r, %r, %r] [%r, %r, %r] power 5 samples %d d0 0 falloff none }" % (P([R.uniform(-2,0), ly, R.uniform(-2,0)]), *[k*x for x in eu], *[k*x for x in ev], smp))
    out.append("plane { point %s normal [0, 1, 0] material { Kd 0.7 } }" % P([0,0,0]))
    n = R.choice([50, 200, 600])
    sz = R.choice([0.02, 0.1, 0.002])
    yspan = R.choice([(0, 1), (0, 0.05), (ly-0.1, ly+0.1)])
    for _ in range(n):
        c = [R.uniform(-2,2), R.uniform(*yspan), R.uniform(-2,2)]
        m = "material { Kd %r t %r ior 1 }" % (R.uniform(0.1,0.9), R.choice([0.3, 0.5, 0.9, 0.7])) if R.random()<0.8 else "material { Kd 0.5 }"
        t = R.random()
        if t < 0.4:
            a=[c[i]-sz*R.uniform(0.2,1) for i in range(3)]; b=[c[i]+sz*R.uniform(0.2,1) for i in range(3)]
            out.append("box { from %s to %s %s }" % (P(a), P(b), m))
        elif t < 0.7:
            v=[[c[i]+R.uniform(-sz,sz)*3 for i in range(3)] for _ in range(3)]
            out.append("triangle { vertices %s %s %s %s }" % (P(v[0]),P(v[1]),P(v[2]), m))
        elif t < 0.85:
            out.append("sphere { center %s radius %s %s }" % (P(c), S(sz), m))
        else:
            out.append("box { from [-1, -1, -1] to [1, 1, 1] scale [%r, %r, %r] rotate [%r, %r, 0] translate %s %s }" % (k*sz, k*sz*R.choice([0.01,1,5]), k*sz, R.uniform(0,90), R.uniform(0,90), P(c), m))
    return "\n".join(out)+"\n"
if __name__ == "__main__":
    sys.stdout.write(gen(int(sys.argv[1])))
