# The `coatings` target: a coating bonded to an elastic substrate (E1/E2 = 2, 10: hard
# coatings; 0.1, 0.01: soft ones; nu = nu2 = 0.3), sphere and cylinder: the frictionless
# load ratio and k(c/a) against a/h = 0.01 ... 1000 (both geometries) and the work of a
# load cycle against a_max/h = 0.01 ... 16 (a figure and a table; the cycle's a_max/h beyond
# is stated as not covered). Not part of `all`: run `snakemake --cores 2 coatings`.


rule coatings_study:
    output:
        png=report(
            f"{RESULTS}figures/coatings.png",
            caption="../report/coatings.rst",
            category="Figures",
            labels={"figure": "Coatings: frictionless load, k and cycle work against a/h",
                    "file": "coatings.png"},
        ),
        pdf=f"{RESULTS}figures/coatings.pdf",
        csv=f"{RESULTS}tables/coatings.csv",
    params:
        version=VERSION,
    log:
        f"{RESULTS}logs/coatings/study.log",
    conda:
        "../envs/contactlib.yaml"
    threads: 1
    resources:
        mem_mb=1000,
        runtime=20,
    script:
        "../scripts/coatings_study.py"


rule coatings:
    input:
        rules.coatings_study.output,
    default_target: False
