from chk import run
import itertools
worst=[]
cases=[]
for h in [1.5, 1e-3, 100, 1e6, 1e-7]:
  for a in [1e-9, 1e-4*h, 0.05*h, 0.24*h, 0.26*h, 0.3*h, 2*h]:
    for fo,d0 in [('inverse_square',0),('inverse_square',1),('linear',0),('linear',0.5),('none',0),('inverse_square',1e-9)]:
      for W in [8*h, 100*h]:
        cases.append((h,a,fo,d0,W))
import sys
bad=0
for c in cases:
    r,o=run(*c)
    if r is None:
        print("ERR",c,o.strip()[:200]); continue
    m=max(abs(x[3]) for x in r if x[3] is not None) if any(x[3] is not None for x in r) else 0
    if m>1e-6: print("BAD",c,m, [x for x in r if x[3] is not None and abs(x[3])>1e-6][:2]); bad+=1
print("cases",len(cases),"bad",bad)
