"""perturbed_regular.py FIRST LAST: regular polygons (n in 5, 7, 12, 64;
radius 1) with every coordinate perturbed uniformly by up to eps (1e-12 ..
1e-2), unit or integer weights, seeds FIRST..LAST-1; naive against deforming
(compare_skeletons.compare, the strict comparison of the tests).  Prints the
cases that differ or fall back.  Run from the repository root."""
import math, os, random, subprocess, sys, json
sys.path.insert(0,'scripts'); sys.path.insert(0,'tests')
import compare_skeletons as cs
W=os.environ.get('WSKEL_BIN', 'bin/wskel')
bad=0; fb=0
for seed in range(int(sys.argv[1]), int(sys.argv[2])):
    rng=random.Random(seed)
    n=rng.choice([5,7,12,64,64,64])
    eps=rng.choice([1e-12,1e-9,1e-7,1e-6,1e-5,1e-4,1e-3,1e-2])
    pts=[(math.cos(2*math.pi*i/n)+rng.uniform(-eps,eps), math.sin(2*math.pi*i/n)+rng.uniform(-eps,eps)) for i in range(n)]
    wm=rng.choice(['unit','int'])
    f='/tmp/perturbed_regular_%d.wpoly'%seed
    with open(f,'w') as fh:
        fh.write('%d\n'%n)
        for p in pts: fh.write('%r %r %d\n'%(p[0],p[1], 1 if wm=='unit' else rng.randint(1,3)))
    r1=subprocess.run([W,'--variant','naive','-o','/tmp/perturbed_regular_n.json',f],capture_output=True,text=True)
    r2=subprocess.run([W,'--variant','deforming','--stats','-o','/tmp/perturbed_regular_d.json',f],capture_output=True,text=True)
    if r1.returncode or r2.returncode:
        print(seed,n,eps,wm,'rc',r1.returncode,r2.returncode, r2.stderr.strip()[:200]); bad+=1; continue
    if 'reference_fallbacks' in r2.stderr and any(l.split()[0]=='reference_fallbacks' and l.split()[1]!='0' for l in r2.stderr.splitlines() if l.strip()):
        fb+=1; print(seed,n,eps,wm,'fallback'); continue
    res=cs.compare(cs.load('/tmp/perturbed_regular_n.json'), cs.load('/tmp/perturbed_regular_d.json'))
    if not res.identical: print(seed,n,eps,wm,'DIFF',res.summary()[:200]); bad+=1
print('bad',bad,'fallback',fb)
