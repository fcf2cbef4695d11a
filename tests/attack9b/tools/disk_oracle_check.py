import sys, struct, subprocess, mpmath as mp
mp.mp.dps = 15
B="/work/wt/attack9b/build/refray"
def readpfm(fn):
    f=open(fn,'rb'); hdr=f.readline().strip(); wh=f.readline().split(); sc=float(f.readline())
    w,h=int(wh[0]),int(wh[1]); n=3 if hdr==b'PF' else 1
    data=f.read(); fmt=('<' if sc<0 else '>')+'%df'%(w*h*n)
    v=struct.unpack(fmt,data); return w,h,[v[i*n:(i+1)*n] for i in range(w*h)]
def run(h, a, falloff, d0, W, tilt=0.0, npx=7, power=10.0, kd=0.5):
    # disk centred at (0,h,0) facing down; ortho camera above, looking down, view width W along x
    sc = f"""oracle disk_light
image {{ width {npx} height 1 samples 1 max_depth 1 background 0 }}
camera {{ orthographic width {W!r} eye [0, {2*h+1!r}, 0] look_at [0, 0, 0] up [0, 0, 1] }}
ambient {{ color 0 }}
distributed_light {{ disk [0, {h!r}, 0] [0, -1, 0] {a!r} power {power!r} samples 16 d0 {d0!r} falloff {falloff} }}
plane {{ point [0, 0, 0] normal [0, 1, 0] material {{ Kd {kd!r} }} }}
"""
    open('/tmp/a9b/or/t.scene','w').write(sc)
    p=subprocess.run(["nice","-n","19",B,"oracle","/tmp/a9b/or/t.scene","-o","/tmp/a9b/or/t.pfm"],capture_output=True,text=True)
    if p.returncode: return None, p.stderr
    w,hh,px=readpfm('/tmp/a9b/or/t.pfm')
    res=[]
    for i in range(w):
        # pixel centre x: ortho; sign of x unknown -> radial distance symmetric
        xc = (i+0.5)/w - 0.5
        r0 = abs(xc)*W
        h_=mp.mpf(h); A=mp.mpf(a); d0_=mp.mpf(d0)
        def phi(d):
            s=d+d0_
            if falloff=='none': return h_/d
            if falloff=='linear': return h_/(d*s)
            return h_/(d*s*s)
        f=lambda rho,t: rho*phi(mp.sqrt(h_**2+(r0+rho*mp.cos(t))**2+(rho*mp.sin(t))**2))
        I = 2*mp.quad(lambda rho: mp.quad(lambda t: f(rho,t),[0,mp.pi/2,mp.pi],method="gauss-legendre"),[0,A/2,A],method="gauss-legendre")
        mean = I/(mp.pi*A*A)
        exp = kd*power*mean
        res.append((r0, float(exp), px[i][0], float((px[i][0]-exp)/exp) if exp else None))
    return res, p.stdout
if __name__=="__main__":
    args=sys.argv[1:]
    r,o=run(float(args[0]),float(args[1]),args[2],float(args[3]),float(args[4]))
    if r is None: print("ERR",o); sys.exit()
    for x in r: print("r0=%.6g exp=%.10g got=%.10g rel=%s"%x)
