# The `stresses` target: subsurface stresses of the sphere (nu = 0.3) in partial slip
# (c/a = 0 ... 0.9, n = 256), the surface radial stress near the edge for rigid and
# elastic indenters, and the sphere pressed then pushed along x (sliding at mu = 0, 0.2,
# 0.4; Cattaneo-Mindlin at mu = 0.4, Q/(mu P) = 0.5): the fields (netCDF), four figures
# and a table of the maxima. Not part of `all`: run `snakemake --cores 2 stresses`.


rule stresses_study:
    output:
        fields=directory(f"{RESULTS}stresses"),
        maps=report(
            f"{RESULTS}figures/stresses-maps.png",
            caption="../report/stresses.rst",
            category="Figures",
            labels={"figure": "Subsurface stresses: partial slip", "file": "stresses-maps.png"},
        ),
        maxima=f"{RESULTS}figures/stresses-maxima.png",
        edge=f"{RESULTS}figures/stresses-edge.png",
        tangential=report(
            f"{RESULTS}figures/stresses-tangential.png",
            caption="../report/stresses.rst",
            category="Figures",
            labels={"figure": "Subsurface stresses: tangential load",
                    "file": "stresses-tangential.png"},
        ),
        csv=f"{RESULTS}tables/stresses.csv",
    params:
        version=VERSION,
    log:
        f"{RESULTS}logs/stresses/study.log",
    conda:
        "../envs/contactlib.yaml"
    threads: 1
    resources:
        mem_mb=1000,
        runtime=10,
    script:
        "../scripts/stresses_study.py"


rule stresses:
    input:
        rules.stresses_study.output,
    default_target: False
