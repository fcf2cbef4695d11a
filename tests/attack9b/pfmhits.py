import sys,struct
def rd(fn):
    f=open(fn,'rb'); hdr=f.readline().strip(); wh=f.readline().split(); sc=float(f.readline())
    w,h=int(wh[0]),int(wh[1]); n=3 if hdr==b'PF' else 1
    v=struct.unpack(('<' if sc<0 else '>')+'%df'%(w*h*n),f.read()); return w,h,n,v
for fn in sys.argv[1:]:
    w,h,n,v=rd(fn); bg=struct.unpack('f',struct.pack('f',0.1))[0]
    rows=[]
    for y in range(h):
        rows.append(''.join('.' if v[(y*w+x)*n]==bg else '#' for x in range(w)))
    print(fn, sum(r.count('#') for r in rows), "hit pixels"); print('\n'.join(rows[::-1] if sc_flip else rows)) if False else print('\n'.join(rows))
