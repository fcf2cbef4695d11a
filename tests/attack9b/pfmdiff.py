import sys,struct
def rd(fn):
    f=open(fn,'rb'); hdr=f.readline().strip(); wh=f.readline().split(); sc=float(f.readline())
    w,h=int(wh[0]),int(wh[1]); n=3 if hdr==b'PF' else 1
    v=struct.unpack(('<' if sc<0 else '>')+'%df'%(w*h*n),f.read()); return w,h,n,v
w,h,n,a=rd(sys.argv[1]); _,_,_,b=rd(sys.argv[2])
c=0
for i in range(w*h):
    if a[i*n:(i+1)*n]!=b[i*n:(i+1)*n]:
        c+=1
        if c<=5: print("pixel x=%d y=%d"%(i%w,i//w), a[i*n:(i+1)*n], b[i*n:(i+1)*n])
print("differing pixels",c,"of",w*h)
