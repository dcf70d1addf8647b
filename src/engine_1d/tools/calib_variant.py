#!/usr/bin/python3
"""Calibration sweep helper: writes a variant of config/engine_1d.yaml + engine_1d_cylinder.yaml
with overrides, runs engine_1d_motoring (motoring-curve check) and engine_1d_steady (default
subset 9 speeds x 7 loads), prints BSFC mean/max |error|, motoring error range, NOx and the
BSFC error table (set RV=-q to skip the table).
usage: calib_variant.py NAME "{'e:calibration/woschni_multiplier': 1.0, 'c:friction/A_bar': 0.05}" [steady args]
  keys 'e:<path>' under engine_1d/, 'c:<path>' under cylinder/; output in $CALIB_OUT/NAME
  env: HBT_SOURCE_DIR (repo root, default .), HBT_BUILD_DIR (default build; the tools are looked
  up in <build>/devel/lib/hybrid_bus_twin, else <build>/src/engine_1d), CALIB_OUT (default
  /tmp/calib/v), WHTC=1 also runs engine_1d_whtc (full cycle, ~1 min CPU) and prints its fuel vs
  the map, NOx and torque regression. Steady statistics: all points and the BSFC validation
  region (column in_region). Run with /usr/bin/python3 (numpy, yaml)."""
import sys, os, yaml, subprocess, csv, json
import numpy as np
R=os.path.abspath(os.environ.get('HBT_SOURCE_DIR','.')); B=os.path.abspath(os.environ.get('HBT_BUILD_DIR','build'))
B=B+'/devel/lib/hybrid_bus_twin' if os.path.exists(B+'/devel/lib/hybrid_bus_twin/engine_1d_steady') else B+'/src/engine_1d'
import ast
name=sys.argv[1]; ov=ast.literal_eval(sys.argv[2]) if len(sys.argv)>2 else {}
args=sys.argv[3:] or ['--speeds','9','--loads','7']
d=os.environ.get('CALIB_OUT','/tmp/calib/v')+f'/{name}'; os.makedirs(d,exist_ok=True)
E_=yaml.safe_load(open(f'{R}/config/engine_1d.yaml')); C_=yaml.safe_load(open(f'{R}/config/engine_1d_cylinder.yaml'))
def setp(doc,path,v):
  ks=path.split('/'); x=doc
  for k in ks[:-1]: x=x[k]
  x[ks[-1]]=v
for k,v in ov.items():
  f,p=k.split(':',1)
  if f=='e': setp(E_['engine_1d'],p,v)
  else: setp(C_['cylinder'],p,v)
E_['engine_1d']['files']['cylinder']=f'{d}/cyl.yaml'  # the others from the repo's config/
E_['engine_1d']['files']['turbo']=f'{R}/config/engine_1d_turbo.yaml'; E_['engine_1d']['files']['reference']=f'{R}/config/engine_map.yaml'
yaml.safe_dump(E_,open(f'{d}/engine.yaml','w')); yaml.safe_dump(C_,open(f'{d}/cyl.yaml','w'))
json.dump(ov,open(f'{d}/overrides.json','w'),indent=1)
mot=subprocess.run(['nice',f'{B}/engine_1d_motoring','--root',R,'--config',f'{d}/engine.yaml','--out',f'{d}/motoring.csv'],capture_output=True,text=True)
open(f'{d}/motoring.txt','w').write(mot.stdout+mot.stderr)
st=subprocess.run(['nice',f'{B}/engine_1d_steady','--root',R,'--config',f'{d}/engine.yaml','--out',d,'--no-plot']+args,capture_output=True,text=True)
open(f'{d}/steady.txt','w').write(st.stdout+st.stderr)
r=list(csv.DictReader(open(f'{d}/steady_points.csv')))
e=np.array([float(x['bsfc_err_pct']) for x in r]); conv=sum(int(x['converged']) for x in r)
m=list(csv.DictReader(open(f'{d}/motoring.csv')))
merr=[float(x['err_pct']) for x in m]
nox=np.array([float(x['nox_g_kWh']) for x in r])
print(f'{name}: n={len(r)} conv={conv} mean|e|={np.mean(abs(e)):.2f} max|e|={np.max(abs(e)):.1f} bias={np.mean(e):+.2f} | motoring err {min(merr):+.1f}..{max(merr):+.1f}% mean|{np.mean(np.abs(merr)):.1f}| | NOx median {np.median(nox):.1f} max {nox.max():.1f}')
ins=np.array([x.get('in_region','1')=='1' for x in r])
if ins.any(): print(f'{name}: region ({ins.sum()} points) mean|e|={np.mean(abs(e[ins])):.2f} max|e|={np.max(abs(e[ins])):.2f} | NOx median {np.median(nox[ins]):.1f}')
if os.environ.get('WHTC')=='1':
  w=subprocess.run(['nice',f'{B}/engine_1d_whtc','--root',R,'--config',f'{d}/engine.yaml','--out',f'{d}/whtc','--no-plot'],capture_output=True,text=True)
  open(f'{d}/whtc.txt','w').write(w.stdout+w.stderr)
  for l in (w.stdout+w.stderr).splitlines():
    if l.startswith('cumulative fuel') or l.startswith('engine-out NOx') or 'torque [Nm]' in l or 'FAIL' in l or 'whtc:' in l: print(f'{name}: WHTC '+l.strip())
sp=sorted(set(float(x['speed_rpm']) for x in r)); ld=sorted(set(float(x['load']) for x in r))
if '-q' not in os.environ.get('RV',''):
  print('load  '+' '.join('%6.0f'%s for s in sp))
  for l in ld:
    row=''
    for s in sp:
      q=[x for x in r if float(x['speed_rpm'])==s and float(x['load'])==l]
      row+=('%6.1f'%float(q[0]['bsfc_err_pct'])+('*' if q[0]['converged']=='0' else ' ')) if q else '   -   '
    print('%5.3f '%l+row)
