import random, sys
def gen(seed):
    R = random.Random(seed)
    k = R.choice([1, 1, 1e-6, 1e6, 2**-30, 1e-3, 2**200, 2**-60])
    o = R.choice([0, 0, 1e7, 1e15, -3.3e7, 1e-6, 2**300 if k > 1e5 else 1e7])
    off = [o*R.choice([1,0,-1,0.5]) for _ in range(3)]
    def P(v): return "[%r, %r, %r]" % tuple(off[i] + k*v[i] for i in range(3))
    def S(x): return "%r" % (k*x)
    out = []
    w, h = 20, 15
    out.append("image { width %d height %d samples 1 max_depth %d background 0.1 }" % (w, h, R.choice([1,2,3])))
    eye = [R.uniform(-3,3), R.uniform(2,6), R.uniform(-6,-3)]
    out.append("camera { perspective eye %s look_at %s up [0, 1, 0] fov 60 }" % (P(eye), P([0,0.5,0])))
    out.append("ambient { color 0.05 }")
    nl = R.choice([1,1,2])
    for _ in range(nl):
        c = [R.uniform(-2,2), R.choice([R.uniform(0.01,4), 0.0, 1.0, R.uniform(5,50)]), R.uniform(-2,2)]
        smp = R.choice([4, 16, 64, 256, 1024])
        fo = R.choice(["inverse_square","linear","none"]) 
        d0 = R.choice(["0", "1"])
        if R.random() < 0.5:
            nrm = R.choice([[0,-1,0],[0,1,0],[1,0,0],[R.uniform(-1,1),R.uniform(-1,1),R.uniform(-1,1)]])
            rad = R.choice([1, 0.01, 1e-5, 3, 0.3])
            out.append("distributed_light { disk %s %s %s power %r samples %d d0 %s falloff %s }" % (P(c), "[%r, %r, %r]" % tuple(nrm), S(rad), R.uniform(1,20)*(k*k if fo=="inverse_square" else (k if fo=="linear" else 1)) if False else R.uniform(1,20), smp, d0, fo))
        else:
            eu = R.choice([[2,0,0],[1e-5,0,0],[R.uniform(-2,2),R.uniform(-2,2),R.uniform(-2,2)]])
            ev = R.choice([[0,0,1.5],[0,1e-5,1e-5],[R.uniform(-2,2),R.uniform(-2,2),R.uniform(-2,2)]])
            out.append("distributed_light { rectangle %s [%r, %r, %r] [%r, %r, %r] power %r samples %d d0 %s falloff %s }" % (P(c), *[k*x for x in eu], *[k*x for x in ev], R.uniform(1,20), smp, d0, fo))
    def mat():
        if R.random() < 0.4:
            return "material { Kd %r t %r ior %r }" % (R.uniform(0,1), R.uniform(0.1,0.95), R.choice([1, 1, 1.5]))
        return "material { Kd %r Ks %r }" % (R.uniform(0,1), R.choice([0, 0.3]))
    if R.random() < 0.7:
        out.append("plane { point %s normal [0, 1, 0] %s }" % (P([0,0,0]), mat()))
    n = R.choice([3, 10, 40, 150])
    for _ in range(n):
        c = [R.uniform(-2.5,2.5), R.uniform(0,3), R.uniform(-2.5,2.5)]
        sz = R.choice([0.3, 0.05, 1e-4, 0.8])
        t = R.random()
        if t < 0.3:
            out.append("sphere { center %s radius %s %s }" % (P(c), S(sz), mat()))
        elif t < 0.6:
            a = [c[i]-sz*R.uniform(0.1,1) for i in range(3)]; b = [c[i]+sz*R.uniform(0.1,1) for i in range(3)]
            if R.random()<0.2: b[1] = a[1] + sz*1e-6
            extra = ""
            if R.random() < 0.3:
                extra = ""
            if any(P(a).split(",")[i]==P(b).split(",")[i] for i in range(3)): continue
            out.append("box { from %s to %s %s }" % (P(a), P(b), mat()))
        elif t < 0.85:
            v = [[c[i]+R.uniform(-sz,sz)*2 for i in range(3)] for _ in range(3)]
            out.append("triangle { vertices %s %s %s %s }" % (P(v[0]), P(v[1]), P(v[2]), mat()))
        else:
            # kept frame: non-uniform scale about origin then translate
            sx, sy, sz2 = R.choice([1,3,0.01]), R.choice([1,0.001,5]), R.choice([1,2])
            out.append("sphere { center [0, 0, 0] radius %s scale [%r, %r, %r] rotate [%r, %r, %r] translate %s %s }" % (S(sz), sx, sy, sz2, R.uniform(0,90), R.uniform(0,90), 0, P(c), mat()))
    return "\n".join(out) + "\n"
if __name__ == "__main__":
    sys.stdout.write(gen(int(sys.argv[1])))
